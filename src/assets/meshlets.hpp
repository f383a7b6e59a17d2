// Cuts large primitives into meshlets (meshoptimizer's builder): runs of up to
// kMeshletTriangles nearby triangles, each with a bounding sphere and a normal
// cone, so that culling can drop the parts of a huge primitive that are outside
// the view or face away (Sponza is 25 primitives of up to 60k triangles). The
// index list is reordered so that every meshlet is one contiguous range.
#pragma once

#include <cstdint>
#include <span>

#include "assets/mesh_asset.hpp"

namespace atrium::assets {

inline constexpr std::size_t kMeshletVertices = 128;
inline constexpr std::size_t kMeshletTriangles = 256;
// Smaller primitives are culled whole: a meshlet's draw command would cost more
// than the triangles it saves.
inline constexpr std::size_t kMeshletMinTriangles = 2 * kMeshletTriangles;

// meshoptimizer's builder looks at the triangles around each vertex it takes
// in, so its cost grows with how many triangles share a vertex: one 1,024-gon
// repeated 100 times (a 400 KiB hostile OBJ, 102,200 triangles on 1,024
// vertices) took 12 s to cut. Real meshes share a vertex among about six
// triangles (a sum of squares per triangle near 20; cone and disc fans well
// under this limit): primitives far beyond it are culled whole instead.
inline constexpr double kMeshletMaxSharing = 256.0;

// How widely a primitive's triangles share vertices: the sum over vertices of
// the square of the triangles using each, per triangle.
[[nodiscard]] double vertex_sharing(std::span<const std::uint32_t> indices, std::size_t vertex_count);

// Builds the meshlets of every opaque or alpha-masked primitive of at least
// kMeshletMinTriangles triangles (blended ones keep their triangle order, which
// blending sees) whose vertex sharing is within kMeshletMaxSharing. Double-sided
// materials get no normal cone.
void build_meshlets(MeshAsset& asset);

// Calls `run(first_index, index_count)` (within the primitive's indices) for
// each run of consecutive meshlets that `keep(m)` accepts (m indexes
// `meshlets`), so that a pass draws one range per run rather than one per
// meshlet.
template <typename Keep, typename Run>
void for_each_meshlet_run(std::span<const Meshlet> meshlets, Keep keep, Run run) {
  std::uint32_t first = 0, count = 0;
  for (std::size_t m = 0; m < meshlets.size(); ++m) {
    if (!keep(m)) {
      if (count > 0) run(first, count);
      count = 0;
    } else if (count > 0 && first + count == meshlets[m].first_index) {
      count += meshlets[m].index_count;
    } else {
      if (count > 0) run(first, count);
      first = meshlets[m].first_index;
      count = meshlets[m].index_count;
    }
  }
  if (count > 0) run(first, count);
}

}  // namespace atrium::assets
