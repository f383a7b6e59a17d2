#include "render/shadows/atlas_allocator.hpp"

#include <bit>
#include <stdexcept>

namespace atrium::shadows {
namespace {

bool power_of_two(int n) { return n > 0 && std::has_single_bit(static_cast<unsigned>(n)); }

}  // namespace

AtlasAllocator::AtlasAllocator(int size, int min_tile) : size_(size), min_tile_(min_tile) {
  if (!power_of_two(size) || !power_of_two(min_tile) || min_tile > size) {
    throw std::invalid_argument("shadow atlas: size and smallest tile must be powers of two, the tile no larger");
  }
  clear();
}

int AtlasAllocator::level_of(int tile_size) const {
  int level = 0;
  for (int s = size_; s > tile_size; s /= 2) ++level;
  return level;
}

void AtlasAllocator::clear() {
  free_.assign(static_cast<std::size_t>(level_of(min_tile_)) + 1, {});
  free_[0].insert({0, 0});
}

std::optional<AtlasTile> AtlasAllocator::allocate(int size) {
  if (!power_of_two(size) || size < min_tile_ || size > size_) return std::nullopt;
  const int level = level_of(size);
  // The smallest free tile that holds the request, split down to its size.
  int from = level;
  while (from >= 0 && free_[static_cast<std::size_t>(from)].empty()) --from;
  if (from < 0) return std::nullopt;
  auto node = free_[static_cast<std::size_t>(from)].begin();
  glm::ivec2 origin(node->first, node->second);
  free_[static_cast<std::size_t>(from)].erase(node);
  for (int l = from; l < level; ++l) {
    const int half = size_ >> (l + 1);
    // Keep the lower-left quarter; the other three become free at the next level.
    auto& next = free_[static_cast<std::size_t>(l) + 1];
    next.insert({origin.x + half, origin.y});
    next.insert({origin.x, origin.y + half});
    next.insert({origin.x + half, origin.y + half});
  }
  return AtlasTile{origin, size};
}

void AtlasAllocator::release(AtlasTile tile) {
  int level = level_of(tile.size);
  glm::ivec2 origin = tile.origin;
  while (level > 0) {
    const int parent_size = tile.size * 2;
    const glm::ivec2 parent(origin.x & ~(parent_size - 1), origin.y & ~(parent_size - 1));
    auto& here = free_[static_cast<std::size_t>(level)];
    bool siblings_free = true;
    for (int q = 0; q < 4; ++q) {
      const std::pair<int, int> sibling{parent.x + (q & 1) * tile.size, parent.y + (q >> 1) * tile.size};
      if (sibling != std::pair<int, int>{origin.x, origin.y} && !here.count(sibling)) siblings_free = false;
    }
    if (!siblings_free) break;
    for (int q = 0; q < 4; ++q) here.erase({parent.x + (q & 1) * tile.size, parent.y + (q >> 1) * tile.size});
    origin = parent;
    tile.size = parent_size;
    --level;
  }
  free_[static_cast<std::size_t>(level)].insert({origin.x, origin.y});
}

long long AtlasAllocator::free_texels() const {
  long long texels = 0;
  for (std::size_t level = 0; level < free_.size(); ++level) {
    const long long side = size_ >> level;
    texels += static_cast<long long>(free_[level].size()) * side * side;
  }
  return texels;
}

}  // namespace atrium::shadows
