// Entity handles: an index into the registry's slot table plus the generation the
// slot had when the handle was made. Destroying an entity bumps its slot's
// generation, so every handle still held elsewhere is detected as stale.
#pragma once

#include <compare>
#include <cstdint>
#include <functional>

namespace atrium::ecs {

struct Entity {
  std::uint32_t index = kInvalidIndex;
  std::uint32_t generation = 0;

  static constexpr std::uint32_t kInvalidIndex = 0xffffffffu;

  [[nodiscard]] constexpr bool is_null() const { return index == kInvalidIndex; }
  constexpr auto operator<=>(const Entity&) const = default;
};

inline constexpr Entity kNullEntity{};

}  // namespace atrium::ecs

template <>
struct std::hash<atrium::ecs::Entity> {
  std::size_t operator()(const atrium::ecs::Entity& e) const noexcept {
    // Both halves in 64 bits, hashed to size_t: 32 bits in the WebAssembly build.
    return std::hash<std::uint64_t>{}((std::uint64_t{e.generation} << 32) | e.index);
  }
};
