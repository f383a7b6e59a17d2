// Cuts large primitives into meshlets (meshoptimizer's builder): runs of up to
// kMeshletTriangles nearby triangles, each with a bounding sphere and a normal
// cone, so that culling can drop the parts of a huge primitive that are outside
// the view or face away (Sponza is 25 primitives of up to 60k triangles). The
// index list is reordered so that every meshlet is one contiguous range.
#pragma once

#include "assets/mesh_asset.hpp"

namespace atrium::assets {

inline constexpr std::size_t kMeshletVertices = 128;
inline constexpr std::size_t kMeshletTriangles = 256;
// Smaller primitives are culled whole: a meshlet's draw command would cost more
// than the triangles it saves.
inline constexpr std::size_t kMeshletMinTriangles = 2 * kMeshletTriangles;

// Builds the meshlets of every opaque or alpha-masked primitive of at least
// kMeshletMinTriangles triangles (blended ones keep their triangle order, which
// blending sees). Double-sided materials get no normal cone.
void build_meshlets(MeshAsset& asset);

}  // namespace atrium::assets
