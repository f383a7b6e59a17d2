// build_meshlets for the WebAssembly build, which has no libmeshoptimizer:
// primitives stay whole, and culling takes or drops each one entire (what the
// native build does below kMeshletMinTriangles).
#include "assets/meshlets.hpp"

namespace atrium::assets {

void build_meshlets(MeshAsset&) {}

}  // namespace atrium::assets
