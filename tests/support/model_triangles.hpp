// Triangles an imported model draws: every instance's mesh, counted once per
// instance (shared by the importer tests).
#pragma once

#include <cstddef>

#include "assets/asset_manager.hpp"
#include "assets/model_import.hpp"

namespace atrium::testing {

inline std::size_t drawn_triangles(const assets::AssetManager& assets, const assets::ModelImport& model) {
  std::size_t count = 0;
  for (const assets::SceneInstance& instance : model.instances) {
    count += assets::triangle_count(assets.mesh_asset(model.asset).meshes.at(instance.mesh));
  }
  return count;
}

}  // namespace atrium::testing
