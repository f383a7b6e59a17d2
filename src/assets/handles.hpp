// Handles that components hold instead of pointers or GL names: an index into
// the AssetManager's tables. The default value means "none".
#pragma once

#include <cstdint>

namespace atrium::assets {

template <typename Tag>
struct Handle {
  static constexpr std::uint32_t kNone = 0xffffffffu;
  std::uint32_t index = kNone;

  [[nodiscard]] constexpr bool valid() const { return index != kNone; }
  constexpr bool operator==(const Handle&) const = default;
};

using MeshAssetHandle = Handle<struct MeshAssetTag>;
using TextureHandle = Handle<struct TextureTag>;

}  // namespace atrium::assets
