// Procedural geometry for the built-in scene: tessellated rectangles, boxes,
// surfaces of revolution (columns, balusters, lamps, the fountain), spheres and
// arch panels. Every shape comes out as assets::Geometry with normals, tangents
// and UVs, exactly as glTF import delivers them.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "assets/mesh_asset.hpp"

namespace atrium::assets::shapes {

// A rectangle from `origin` spanning `edge_u` and `edge_v`, cut into nu x nv quads,
// facing cross(edge_u, edge_v). UVs are world lengths times uv_scale.
[[nodiscard]] Geometry grid(glm::vec3 origin, glm::vec3 edge_u, glm::vec3 edge_v, int nu, int nv, float uv_scale);
[[nodiscard]] Geometry box(glm::vec3 min, glm::vec3 max, float uv_scale);
// Revolves a profile of (radius, height) points around +Y. Joints where the
// profile turns by more than 35 degrees stay sharp.
[[nodiscard]] Geometry lathe(const std::vector<glm::vec2>& profile, int segments, float uv_scale);
[[nodiscard]] Geometry sphere(float radius, int segments, int rings);
// A wall panel with a semicircular opening: the opening's centre is the origin,
// its radius `inner_radius`; the panel spans [-half_width, half_width] x [0, height]
// in X/Y and `depth` in Z, with the curved underside (intrados) included.
[[nodiscard]] Geometry arch_panel(float inner_radius, float half_width, float height, float depth, int segments,
                                   float uv_scale);

// Appends `source`, transformed, to `target` (same material).
void append(Geometry& target, const Geometry& source, const glm::mat4& transform);

}  // namespace atrium::assets::shapes
