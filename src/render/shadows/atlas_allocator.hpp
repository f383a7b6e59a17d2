// Square tiles of power-of-two sides in a square power-of-two shadow atlas: a
// quadtree ("buddy") allocator. A tile is split into four to serve a smaller
// request and merged again when its four quarters are free, so tiles whose
// areas add up to at most the atlas's always fit when placed largest first.
// Pure CPU bookkeeping, testable without GL.
#pragma once

#include <optional>
#include <set>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

namespace atrium::shadows {

struct AtlasTile {
  glm::ivec2 origin{0};  // texels from the atlas's lower-left corner
  int size = 0;          // side in texels
  bool operator==(const AtlasTile&) const = default;
};

class AtlasAllocator {
 public:
  // `size` and `min_tile` are powers of two, min_tile <= size.
  AtlasAllocator(int size, int min_tile);

  // A free tile of side `size` (a power of two between min_tile and the atlas
  // size), or nothing when none is left.
  [[nodiscard]] std::optional<AtlasTile> allocate(int size);
  // Gives back a tile that allocate returned.
  void release(AtlasTile tile);
  // Every tile free again.
  void clear();

  [[nodiscard]] int size() const { return size_; }
  [[nodiscard]] int min_tile() const { return min_tile_; }
  // Texels in free tiles.
  [[nodiscard]] long long free_texels() const;

 private:
  [[nodiscard]] int level_of(int tile_size) const;  // 0: the whole atlas
  int size_;
  int min_tile_;
  // Per level, the origins of its free tiles (ordered, so placement is deterministic).
  std::vector<std::set<std::pair<int, int>>> free_;
};

}  // namespace atrium::shadows
