// An entity drawn with one mesh of a MeshAsset (a glTF node referencing a mesh).
// The entity's Transform places it in the world.
#pragma once

#include <cstdint>

#include "assets/handles.hpp"

namespace atrium {

struct MeshInstance {
  assets::MeshAssetHandle asset;
  std::uint32_t mesh = 0;  // index into the asset's meshes
};

}  // namespace atrium
