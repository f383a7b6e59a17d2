#include "assets/meshlets.hpp"

#include <algorithm>

#include <meshoptimizer.h>

namespace atrium::assets {
namespace {

void build(const std::vector<Vertex>& vertices, bool cones, Primitive& primitive) {
  const std::size_t bound = meshopt_buildMeshletsBound(primitive.indices.size(), kMeshletVertices, kMeshletTriangles);
  std::vector<meshopt_Meshlet> meshlets(bound);
  std::vector<unsigned int> meshlet_vertices(bound * kMeshletVertices);
  std::vector<unsigned char> meshlet_triangles(bound * kMeshletTriangles * 3);
  const float* positions = &vertices[0].position.x;
  // A little weight on normal cones keeps meshlets that can face away whole.
  const std::size_t count = meshopt_buildMeshlets(meshlets.data(), meshlet_vertices.data(), meshlet_triangles.data(),
                                                  primitive.indices.data(), primitive.indices.size(), positions, vertices.size(),
                                                  sizeof(Vertex), kMeshletVertices, kMeshletTriangles, 0.25f);
  std::vector<std::uint32_t> indices;
  indices.reserve(primitive.indices.size());
  primitive.meshlets.clear();
  for (std::size_t m = 0; m < count; ++m) {
    const meshopt_Meshlet& source = meshlets[m];
    const unsigned int* local_vertices = &meshlet_vertices[source.vertex_offset];
    const unsigned char* local_triangles = &meshlet_triangles[source.triangle_offset];
    Meshlet meshlet;
    meshlet.first_index = static_cast<std::uint32_t>(indices.size());
    meshlet.index_count = source.triangle_count * 3;
    for (std::size_t i = 0; i < meshlet.index_count; ++i) indices.push_back(local_vertices[local_triangles[i]]);
    const meshopt_Bounds b = meshopt_computeMeshletBounds(local_vertices, local_triangles, source.triangle_count, positions,
                                                          vertices.size(), sizeof(Vertex));
    meshlet.center = {b.center[0], b.center[1], b.center[2]};
    meshlet.radius = b.radius;
    meshlet.cone_apex = {b.cone_apex[0], b.cone_apex[1], b.cone_apex[2]};
    meshlet.cone_axis = {b.cone_axis[0], b.cone_axis[1], b.cone_axis[2]};
    // meshoptimizer gives 1 where no cone bounds the normals.
    meshlet.cone_cutoff = cones && b.cone_cutoff < 1.0f ? b.cone_cutoff : 2.0f;
    primitive.meshlets.push_back(meshlet);
  }
  primitive.indices = std::move(indices);
}

}  // namespace

double vertex_sharing(std::span<const std::uint32_t> indices, std::size_t vertex_count) {
  if (indices.size() < 3) return 0.0;
  std::vector<std::uint32_t> uses(vertex_count, 0);
  for (const std::uint32_t i : indices) {
    if (i < vertex_count) ++uses[i];
  }
  double squares = 0.0;
  for (const std::uint32_t n : uses) squares += static_cast<double>(n) * n;
  return squares / static_cast<double>(indices.size() / 3);
}

void build_meshlets(MeshAsset& asset) {
  for (Mesh& mesh : asset.meshes) {
    for (Primitive& primitive : mesh.primitives) {
      primitive.meshlets.clear();
      if (primitive.indices.size() / 3 < kMeshletMinTriangles || primitive.material >= asset.materials.size()) continue;
      const Material& material = asset.materials[primitive.material];
      if (material.alpha_mode == AlphaMode::Blend || primitive.vertex_buffer >= asset.vertex_buffers.size()) continue;
      const std::vector<Vertex>& vertices = asset.vertex_buffers[primitive.vertex_buffer];
      if (std::any_of(primitive.indices.begin(), primitive.indices.end(), [&](std::uint32_t i) { return i >= vertices.size(); })) continue;
      if (vertex_sharing(primitive.indices, vertices.size()) > kMeshletMaxSharing) continue;
      build(vertices, !material.double_sided, primitive);
    }
  }
}

}  // namespace atrium::assets
