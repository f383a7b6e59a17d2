#include "assets/mesh_builder.hpp"

#include <cmath>

#include <glm/gtc/constants.hpp>

namespace atrium::assets::shapes {
namespace {

void finish(Geometry& g) { generate_tangents(g); }

void add_quad(Geometry& p, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
  p.indices.insert(p.indices.end(), {a, b, c, a, c, d});
}

}  // namespace

Geometry grid(glm::vec3 origin, glm::vec3 edge_u, glm::vec3 edge_v, int nu, int nv, float uv_scale) {
  Geometry p;
  const glm::vec3 normal = glm::normalize(glm::cross(edge_u, edge_v));
  const float length_u = glm::length(edge_u), length_v = glm::length(edge_v);
  for (int j = 0; j <= nv; ++j) {
    for (int i = 0; i <= nu; ++i) {
      const float s = static_cast<float>(i) / static_cast<float>(nu);
      const float t = static_cast<float>(j) / static_cast<float>(nv);
      Vertex v;
      v.position = origin + edge_u * s + edge_v * t;
      v.normal = normal;
      v.uv0 = glm::vec2(s * length_u, t * length_v) * uv_scale;
      v.uv1 = glm::vec2(s, t);
      p.vertices.push_back(v);
    }
  }
  const auto row = static_cast<std::uint32_t>(nu + 1);
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      const auto a = static_cast<std::uint32_t>(j) * row + static_cast<std::uint32_t>(i);
      add_quad(p, a, a + 1, a + row + 1, a + row);
    }
  }
  finish(p);
  return p;
}

Geometry box(glm::vec3 lo, glm::vec3 hi, float uv_scale) {
  const glm::vec3 size = hi - lo;
  Geometry p;
  const glm::vec3 x(size.x, 0, 0), y(0, size.y, 0), z(0, 0, size.z);
  const Geometry faces[] = {
      grid(glm::vec3(lo.x, lo.y, hi.z), x, y, 1, 1, uv_scale),   // +Z
      grid(glm::vec3(hi.x, lo.y, lo.z), -x, y, 1, 1, uv_scale),  // -Z
      grid(glm::vec3(hi.x, lo.y, hi.z), -z, y, 1, 1, uv_scale),  // +X
      grid(glm::vec3(lo.x, lo.y, lo.z), z, y, 1, 1, uv_scale),   // -X
      grid(glm::vec3(lo.x, hi.y, hi.z), x, -z, 1, 1, uv_scale),  // +Y
      grid(glm::vec3(lo.x, lo.y, lo.z), x, z, 1, 1, uv_scale),   // -Y
  };
  for (const auto& face : faces) append(p, face, glm::mat4(1.0f));
  return p;
}

Geometry lathe(const std::vector<glm::vec2>& profile, int segments, float uv_scale) {
  Geometry p;
  const std::size_t n = profile.size();
  // Outward normal of each profile segment in the (radius, height) plane.
  std::vector<glm::vec2> segment_normals;
  std::vector<float> arc(n, 0.0f);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const glm::vec2 d = profile[i + 1] - profile[i];
    segment_normals.push_back(glm::normalize(glm::vec2(d.y, -d.x)));
    arc[i + 1] = arc[i] + glm::length(d);
  }
  const float sharp_cos = std::cos(glm::radians(35.0f));
  for (std::size_t s = 0; s + 1 < n; ++s) {
    // Each profile segment gets its own ring pair so that sharp joints stay sharp.
    glm::vec2 end_normals[2];
    for (int e = 0; e < 2; ++e) {
      glm::vec2 normal = segment_normals[s];
      const std::size_t neighbour = e == 0 ? s - 1 : s + 1;
      if ((e == 0 && s > 0) || (e == 1 && s + 2 < n)) {
        if (glm::dot(segment_normals[neighbour], normal) > sharp_cos) {
          normal = glm::normalize(segment_normals[neighbour] + normal);
        }
      }
      end_normals[e] = normal;
    }
    const auto base = static_cast<std::uint32_t>(p.vertices.size());
    for (int e = 0; e < 2; ++e) {
      const glm::vec2 point = profile[s + static_cast<std::size_t>(e)];
      for (int k = 0; k <= segments; ++k) {
        const float angle = glm::two_pi<float>() * static_cast<float>(k) / static_cast<float>(segments);
        const float c = std::cos(angle), sn = std::sin(angle);
        Vertex v;
        v.position = glm::vec3(point.x * c, point.y, -point.x * sn);
        v.normal = glm::normalize(glm::vec3(end_normals[e].x * c, end_normals[e].y, -end_normals[e].x * sn));
        v.uv0 = glm::vec2(static_cast<float>(k) / static_cast<float>(segments) * 2.0f, arc[s + static_cast<std::size_t>(e)] * uv_scale);
        v.uv1 = v.uv0;
        p.vertices.push_back(v);
      }
    }
    const auto ring = static_cast<std::uint32_t>(segments + 1);
    for (std::uint32_t k = 0; k < static_cast<std::uint32_t>(segments); ++k) {
      add_quad(p, base + k, base + k + 1, base + ring + k + 1, base + ring + k);
    }
  }
  finish(p);
  return p;
}

Geometry sphere(float radius, int segments, int rings) {
  Geometry p;
  for (int r = 0; r <= rings; ++r) {
    const float phi = glm::pi<float>() * static_cast<float>(r) / static_cast<float>(rings);
    for (int s = 0; s <= segments; ++s) {
      const float theta = glm::two_pi<float>() * static_cast<float>(s) / static_cast<float>(segments);
      Vertex v;
      v.normal = glm::vec3(std::sin(phi) * std::cos(theta), std::cos(phi), -std::sin(phi) * std::sin(theta));
      v.position = v.normal * radius;
      v.uv0 = glm::vec2(static_cast<float>(s) / static_cast<float>(segments), static_cast<float>(r) / static_cast<float>(rings));
      v.uv1 = v.uv0;
      p.vertices.push_back(v);
    }
  }
  const auto row = static_cast<std::uint32_t>(segments + 1);
  for (std::uint32_t r = 0; r < static_cast<std::uint32_t>(rings); ++r) {
    for (std::uint32_t s = 0; s < static_cast<std::uint32_t>(segments); ++s) {
      const std::uint32_t a = r * row + s;
      add_quad(p, a, a + row, a + row + 1, a + 1);
    }
  }
  finish(p);
  return p;
}

Geometry arch_panel(float inner_radius, float half_width, float height, float depth, int segments, float uv_scale) {
  Geometry p;
  const float half_depth = depth * 0.5f;
  // Front (+Z) and back (-Z) faces: quads between the opening's rim and the
  // panel's outline, both sampled along the same rays from the centre.
  for (int side = 0; side < 2; ++side) {
    const float z = side == 0 ? half_depth : -half_depth;
    const glm::vec3 normal(0.0f, 0.0f, side == 0 ? 1.0f : -1.0f);
    const auto base = static_cast<std::uint32_t>(p.vertices.size());
    for (int k = 0; k <= segments; ++k) {
      const float angle = glm::pi<float>() * static_cast<float>(k) / static_cast<float>(segments);
      const glm::vec2 dir(std::cos(angle), std::sin(angle));
      float t = 1e9f;
      if (std::abs(dir.x) > 1e-6f) t = std::min(t, half_width / std::abs(dir.x));
      if (dir.y > 1e-6f) t = std::min(t, height / dir.y);
      for (const glm::vec2 point : {dir * inner_radius, dir * t}) {
        Vertex v;
        v.position = glm::vec3(point, z);
        v.normal = normal;
        v.uv0 = point * uv_scale;
        v.uv1 = v.uv0;
        p.vertices.push_back(v);
      }
    }
    for (std::uint32_t k = 0; k < static_cast<std::uint32_t>(segments); ++k) {
      const std::uint32_t a = base + 2 * k;
      if (side == 0) add_quad(p, a, a + 1, a + 3, a + 2);
      else add_quad(p, a, a + 2, a + 3, a + 1);
    }
  }
  // Intrados: the curved underside, facing the opening's centre.
  const auto base = static_cast<std::uint32_t>(p.vertices.size());
  for (int k = 0; k <= segments; ++k) {
    const float angle = glm::pi<float>() * static_cast<float>(k) / static_cast<float>(segments);
    const glm::vec2 dir(std::cos(angle), std::sin(angle));
    for (const float z : {half_depth, -half_depth}) {
      Vertex v;
      v.position = glm::vec3(dir * inner_radius, z);
      v.normal = glm::vec3(-dir, 0.0f);
      v.uv0 = glm::vec2(angle * inner_radius, z) * uv_scale;
      v.uv1 = v.uv0;
      p.vertices.push_back(v);
    }
  }
  for (std::uint32_t k = 0; k < static_cast<std::uint32_t>(segments); ++k) {
    const std::uint32_t a = base + 2 * k;
    add_quad(p, a, a + 2, a + 3, a + 1);
  }
  finish(p);
  return p;
}

void append(Geometry& target, const Geometry& source, const glm::mat4& transform) {
  const auto offset = static_cast<std::uint32_t>(target.vertices.size());
  const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(transform)));
  for (Vertex v : source.vertices) {
    v.position = glm::vec3(transform * glm::vec4(v.position, 1.0f));
    v.normal = glm::normalize(normal_matrix * v.normal);
    v.tangent = glm::vec4(glm::normalize(glm::mat3(transform) * glm::vec3(v.tangent)), v.tangent.w);
    target.vertices.push_back(v);
  }
  for (auto index : source.indices) target.indices.push_back(index + offset);
}

}  // namespace atrium::assets::shapes
