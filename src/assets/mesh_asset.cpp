#include "assets/mesh_asset.hpp"

#include <cmath>

namespace atrium::assets {

std::size_t MeshAsset::vertex_count() const {
  std::size_t count = 0;
  for (const auto& buffer : vertex_buffers) count += buffer.size();
  return count;
}

Primitive add_geometry(MeshAsset& asset, Geometry geometry, std::uint32_t material) {
  Primitive p;
  p.vertex_buffer = static_cast<std::uint32_t>(asset.vertex_buffers.size());
  p.indices = std::move(geometry.indices);
  p.material = material;
  compute_bounds(geometry.vertices, p);
  asset.vertex_buffers.push_back(std::move(geometry.vertices));
  return p;
}

void compute_bounds(std::span<const Vertex> vertices, Primitive& primitive) {
  if (primitive.indices.empty()) {
    primitive.bounds_min = primitive.bounds_max = glm::vec3(0.0f);
    return;
  }
  primitive.bounds_min = primitive.bounds_max = vertices[primitive.indices.front()].position;
  for (const std::uint32_t i : primitive.indices) {
    primitive.bounds_min = glm::min(primitive.bounds_min, vertices[i].position);
    primitive.bounds_max = glm::max(primitive.bounds_max, vertices[i].position);
  }
}

void generate_normals(std::span<Vertex> vertices, std::span<const std::uint32_t> indices) {
  std::vector<glm::vec3> sums(vertices.size(), glm::vec3(0.0f));
  std::vector<bool> reached(vertices.size(), false);
  for (std::size_t i = 0; i + 2 < indices.size(); i += 3) {
    const auto a = indices[i], b = indices[i + 1], c = indices[i + 2];
    const glm::vec3 p0 = vertices[a].position;
    // The cross product's length is twice the area: larger faces weigh more.
    const glm::vec3 n = glm::cross(vertices[b].position - p0, vertices[c].position - p0);
    for (auto k : {a, b, c}) {
      sums[k] += n;
      reached[k] = true;
    }
  }
  for (std::size_t i = 0; i < sums.size(); ++i) {
    if (!reached[i]) continue;
    const float length = glm::length(sums[i]);
    vertices[i].normal = length > 0.0f ? sums[i] / length : glm::vec3(0.0f, 1.0f, 0.0f);
  }
}

void generate_tangents(std::span<Vertex> vertices, std::span<const std::uint32_t> indices) {
  const std::size_t n = vertices.size();
  std::vector<glm::vec3> tangents(n, glm::vec3(0.0f));
  std::vector<glm::vec3> bitangents(n, glm::vec3(0.0f));
  for (std::size_t i = 0; i + 2 < indices.size(); i += 3) {
    const std::uint32_t idx[3] = {indices[i], indices[i + 1], indices[i + 2]};
    const Vertex& v0 = vertices[idx[0]];
    const Vertex& v1 = vertices[idx[1]];
    const Vertex& v2 = vertices[idx[2]];
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
    const glm::vec3 normal = vertices[i].normal;
    glm::vec3 t = tangents[i] - normal * glm::dot(normal, tangents[i]);
    if (!(glm::dot(t, t) >= 1e-20f)) {
      // No usable UVs: any vector perpendicular to the normal keeps shading defined.
      t = std::abs(normal.x) < 0.9f ? glm::cross(normal, glm::vec3(1, 0, 0)) : glm::cross(normal, glm::vec3(0, 1, 0));
    }
    t = glm::normalize(t);
    const float handedness = glm::dot(glm::cross(normal, t), bitangents[i]) < 0.0f ? -1.0f : 1.0f;
    vertices[i].tangent = glm::vec4(t, handedness);
  }
}

std::vector<std::string> dropped_triangle_lines(const DroppedTriangles& dropped, std::size_t read) {
  std::vector<std::string> lines;
  const auto line = [&](std::size_t count, const char* reason) {
    if (count > 0) lines.push_back(std::to_string(count) + " of " + std::to_string(read) + " triangles " + reason + "; they are skipped");
  };
  line(dropped.non_finite, "have a NaN or infinite corner");
  line(dropped.zero_area, "have zero area");
  return lines;
}

DroppedTriangles drop_unusable_triangles(std::span<const Vertex> vertices, std::vector<std::uint32_t>& indices) {
  auto finite = [](glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
  DroppedTriangles dropped;
  std::size_t kept = 0;
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    const glm::vec3 a = vertices[indices[t]].position, b = vertices[indices[t + 1]].position, c = vertices[indices[t + 2]].position;
    const glm::vec3 n = glm::cross(b - a, c - a);
    if (!finite(a) || !finite(b) || !finite(c) || !finite(n)) {
      ++dropped.non_finite;
      continue;
    }
    if (n == glm::vec3(0.0f)) {
      ++dropped.zero_area;
      continue;
    }
    for (std::size_t k = 0; k < 3; ++k) indices[kept * 3 + k] = indices[t + k];
    ++kept;
  }
  indices.resize(kept * 3);
  return dropped;
}

bool repair_normals(std::span<Vertex> vertices, std::span<const std::uint32_t> triangles) {
  bool bad = false;
  for (Vertex& v : vertices) {
    const float length = glm::length(v.normal);
    if (length > 1e-12f && std::isfinite(length)) v.normal /= length;
    else bad = true;
  }
  if (!bad) return false;
  std::vector<Vertex> smooth(vertices.begin(), vertices.end());
  generate_normals(smooth, triangles);
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    if (!(std::abs(glm::length(vertices[i].normal) - 1.0f) < 1e-3f)) vertices[i].normal = smooth[i].normal;
    if (!(std::abs(glm::length(vertices[i].normal) - 1.0f) < 1e-3f)) vertices[i].normal = glm::vec3(0.0f, 1.0f, 0.0f);
  }
  return true;
}

bool tangents_valid(std::span<const Vertex> vertices) {
  for (const Vertex& v : vertices) {
    const float length = glm::length(glm::vec3(v.tangent));
    if (!std::isfinite(length) || !(length > 1e-6f) || !std::isfinite(v.tangent.w)) return false;
  }
  return true;
}

std::size_t triangle_count(const Mesh& mesh) {
  std::size_t count = 0;
  for (const auto& p : mesh.primitives) count += p.indices.size() / 3;
  return count;
}

}  // namespace atrium::assets
