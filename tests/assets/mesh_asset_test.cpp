#include <gtest/gtest.h>

#include "assets/mesh_asset.hpp"
#include "assets/mesh_builder.hpp"

namespace atrium::assets {
namespace {

TEST(MeshBuilder, GridFacesAlongTheCrossProductOfItsEdges) {
  const Geometry p = shapes::grid(glm::vec3(0), glm::vec3(2, 0, 0), glm::vec3(0, 0, -3), 4, 6, 1.0f);
  EXPECT_EQ(p.vertices.size(), 5u * 7u);
  EXPECT_EQ(p.indices.size(), 4u * 6u * 6u);
  for (const Vertex& v : p.vertices) EXPECT_NEAR(v.normal.y, 1.0f, 1e-6f);
  // Winding agrees with the normal: counter-clockwise seen from +Y.
  const glm::vec3 a = p.vertices[p.indices[0]].position, b = p.vertices[p.indices[1]].position,
                  c = p.vertices[p.indices[2]].position;
  EXPECT_GT(glm::cross(b - a, c - a).y, 0.0f);
  MeshAsset asset;
  const Primitive added = add_geometry(asset, p, 0);
  EXPECT_EQ(added.bounds_min, glm::vec3(0, 0, -3));
  EXPECT_EQ(added.bounds_max, glm::vec3(2, 0, 0));
}

TEST(MeshAsset, PrimitivesSharingAVertexBufferHaveTheBoundsOfWhatTheyIndex) {
  MeshAsset asset;
  asset.vertex_buffers.push_back(shapes::grid(glm::vec3(0), glm::vec3(4, 0, 0), glm::vec3(0, 4, 0), 4, 4, 1.0f).vertices);
  Primitive left, right;
  left.indices = {0, 1, 5};    // (0,0) (1,0) (0,1)
  right.indices = {3, 4, 9};   // (3,0) (4,0) (4,1)
  compute_bounds(asset.vertex_buffers[0], left);
  compute_bounds(asset.vertex_buffers[0], right);
  EXPECT_EQ(left.bounds_min, glm::vec3(0, 0, 0));
  EXPECT_EQ(left.bounds_max, glm::vec3(1, 1, 0));
  EXPECT_EQ(right.bounds_min, glm::vec3(3, 0, 0));
  EXPECT_EQ(right.bounds_max, glm::vec3(4, 1, 0));
  EXPECT_EQ(asset.vertex_count(), 25u);
}

TEST(MeshBuilder, LatheNormalsPointAwayFromTheAxis) {
  const Geometry p = shapes::lathe({{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 2.0f}, {0.0f, 2.0f}}, 16, 1.0f);
  for (const Vertex& v : p.vertices) {
    const glm::vec2 radial(v.position.x, v.position.z);
    if (glm::length(radial) > 0.99f && v.position.y > 0.01f && v.position.y < 1.99f) {
      EXPECT_GT(glm::dot(glm::vec2(v.normal.x, v.normal.z), radial), 0.9f);
    }
  }
}

TEST(MeshAsset, GeneratedNormalsOfAFlatQuadAreItsFaceNormal) {
  Geometry p;
  p.vertices.resize(4);
  p.vertices[0].position = {0, 0, 0};
  p.vertices[1].position = {1, 0, 0};
  p.vertices[2].position = {1, 1, 0};
  p.vertices[3].position = {0, 1, 0};
  p.indices = {0, 1, 2, 0, 2, 3};
  generate_normals(p);
  for (const Vertex& v : p.vertices) EXPECT_NEAR(v.normal.z, 1.0f, 1e-6f);
}

TEST(MeshAsset, GeneratedTangentsFollowIncreasingUAndAreOrthonormal) {
  Geometry p = shapes::grid(glm::vec3(0), glm::vec3(0, 0, -2), glm::vec3(0, 2, 0), 2, 2, 1.0f);
  p.vertices[0].tangent = glm::vec4(0.0f);
  generate_tangents(p);
  for (const Vertex& v : p.vertices) {
    EXPECT_NEAR(glm::length(glm::vec3(v.tangent)), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(glm::vec3(v.tangent), v.normal), 0.0f, 1e-5f);
    EXPECT_NEAR(v.tangent.z, -1.0f, 1e-5f) << "u grows along -Z";
    EXPECT_EQ(v.tangent.w, 1.0f);
  }
}

TEST(MeshAsset, MirroredUvsFlipTheBitangentSign) {
  Geometry p = shapes::grid(glm::vec3(0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), 1, 1, 1.0f);
  for (Vertex& v : p.vertices) v.uv0.y = -v.uv0.y;
  generate_tangents(p);
  for (const Vertex& v : p.vertices) EXPECT_EQ(v.tangent.w, -1.0f);
}

TEST(MeshAsset, TangentsStayDefinedWithoutUvs) {
  Geometry p = shapes::grid(glm::vec3(0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), 1, 1, 1.0f);
  for (Vertex& v : p.vertices) v.uv0 = glm::vec2(0.0f);
  generate_tangents(p);
  for (const Vertex& v : p.vertices) {
    EXPECT_NEAR(glm::length(glm::vec3(v.tangent)), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(glm::vec3(v.tangent), v.normal), 0.0f, 1e-5f);
  }
}

}  // namespace
}  // namespace atrium::assets
