#include "assets/mesh_asset.hpp"

#include <cmath>

namespace atrium::assets {

void compute_bounds(Primitive& primitive) {
  if (primitive.vertices.empty()) {
    primitive.bounds_min = primitive.bounds_max = glm::vec3(0.0f);
    return;
  }
  primitive.bounds_min = primitive.bounds_max = primitive.vertices.front().position;
  for (const auto& v : primitive.vertices) {
    primitive.bounds_min = glm::min(primitive.bounds_min, v.position);
    primitive.bounds_max = glm::max(primitive.bounds_max, v.position);
  }
}

void generate_normals(Primitive& primitive) {
  std::vector<glm::vec3> sums(primitive.vertices.size(), glm::vec3(0.0f));
  for (std::size_t i = 0; i + 2 < primitive.indices.size(); i += 3) {
    const auto a = primitive.indices[i], b = primitive.indices[i + 1], c = primitive.indices[i + 2];
    const glm::vec3 p0 = primitive.vertices[a].position;
    // The cross product's length is twice the area: larger faces weigh more.
    const glm::vec3 n = glm::cross(primitive.vertices[b].position - p0, primitive.vertices[c].position - p0);
    sums[a] += n;
    sums[b] += n;
    sums[c] += n;
  }
  for (std::size_t i = 0; i < sums.size(); ++i) {
    const float length = glm::length(sums[i]);
    primitive.vertices[i].normal = length > 0.0f ? sums[i] / length : glm::vec3(0.0f, 1.0f, 0.0f);
  }
}

void generate_tangents(Primitive& primitive) {
  const std::size_t n = primitive.vertices.size();
  std::vector<glm::vec3> tangents(n, glm::vec3(0.0f));
  std::vector<glm::vec3> bitangents(n, glm::vec3(0.0f));
  for (std::size_t i = 0; i + 2 < primitive.indices.size(); i += 3) {
    const std::uint32_t idx[3] = {primitive.indices[i], primitive.indices[i + 1], primitive.indices[i + 2]};
    const Vertex& v0 = primitive.vertices[idx[0]];
    const Vertex& v1 = primitive.vertices[idx[1]];
    const Vertex& v2 = primitive.vertices[idx[2]];
    const glm::vec3 e1 = v1.position - v0.position, e2 = v2.position - v0.position;
    const glm::vec2 d1 = v1.uv0 - v0.uv0, d2 = v2.uv0 - v0.uv0;
    const float det = d1.x * d2.y - d2.x * d1.y;
    if (std::abs(det) < 1e-12f) continue;  // degenerate UVs say nothing about the tangent
    const float r = 1.0f / det;
    const glm::vec3 t = (e1 * d2.y - e2 * d1.y) * r;
    const glm::vec3 b = (e2 * d1.x - e1 * d2.x) * r;
    for (auto k : idx) {
      tangents[k] += t;
      bitangents[k] += b;
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    const glm::vec3 normal = primitive.vertices[i].normal;
    glm::vec3 t = tangents[i] - normal * glm::dot(normal, tangents[i]);
    if (glm::dot(t, t) < 1e-20f) {
      // No usable UVs: any vector perpendicular to the normal keeps shading defined.
      t = std::abs(normal.x) < 0.9f ? glm::cross(normal, glm::vec3(1, 0, 0)) : glm::cross(normal, glm::vec3(0, 1, 0));
    }
    t = glm::normalize(t);
    const float handedness = glm::dot(glm::cross(normal, t), bitangents[i]) < 0.0f ? -1.0f : 1.0f;
    primitive.vertices[i].tangent = glm::vec4(t, handedness);
  }
}

std::size_t triangle_count(const Mesh& mesh) {
  std::size_t count = 0;
  for (const auto& p : mesh.primitives) count += p.indices.size() / 3;
  return count;
}

}  // namespace atrium::assets
