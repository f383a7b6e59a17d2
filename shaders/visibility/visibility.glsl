// Reading the visibility buffer back into surfaces: an identifier names a
// triangle of the frame (VisibilityUnit in src/render/frame/draw_list.hpp);
// its unit gives the instance record, the record the primitive's indices in
// the geometry pools and the material. The triangle is rebuilt in world space
// and the pixel's ray through it gives position and barycentrics; the rays
// through the pixels of its 2x2 quad give the differences that a raster
// quad's derivatives would, so mip selection matches the raster path's.
// Needs frame.glsl; visible_surface() needs common/material.glsl built with
// EXPLICIT_GRADIENTS (the resolve's) included first.
#include "common/instances.glsl"
#include "common/material_table.glsl"
#include "common/msaa.glsl"

// C++ twin: VisibilityUnit.
struct Unit {
  uint first_id;
  uint record;
};
// C++ twin of the head: VisibilityUnitsHead (why the count, not length()).
layout(std430, binding = 24) readonly buffer Units {
  uint u_unit_count;
  uint u_units_unused;
  Unit u_units[];
};
// assets::Vertex, 16 words: position 0-2, normal 3-5, tangent 6-9, uv0 10-11,
// uv1 12-13, colour 14-15 (four 16-bit unorms). C++ twin: the pools of GpuAssets.
layout(std430, binding = 25) readonly buffer VertexPool { uint u_vertex_words[]; };
layout(std430, binding = 26) readonly buffer IndexPool { uint u_index_pool[]; };
// One identifier a sample with MSAA.
layout(binding = 5) uniform utarget2D u_visibility;

const uint kVertexWords = 16u;

// The unit that holds identifier `id` (> 0): the last whose first identifier
// is at most `id` (units without triangles share their successor's first).
uint find_unit(uint id) {
  uint lo = 0u, hi = u_unit_count;
  while (hi - lo > 1u) {
    uint mid = (lo + hi) / 2u;
    if (u_units[mid].first_id <= id) lo = mid;
    else hi = mid;
  }
  return lo;
}

// The instance record that drew triangle `id`, and the triangle's index in its primitive.
Instance visible_instance(uint id, out uint triangle) {
  Unit unit = u_units[find_unit(id)];
  triangle = id - unit.first_id;
  return u_instances[unit.record];
}

vec3 vertex_vec3(uint v, uint word) {
  uint w = v * kVertexWords + word;
  return uintBitsToFloat(uvec3(u_vertex_words[w], u_vertex_words[w + 1u], u_vertex_words[w + 2u]));
}
vec4 vertex_vec4(uint v, uint word) {
  uint w = v * kVertexWords + word;
  return uintBitsToFloat(uvec4(u_vertex_words[w], u_vertex_words[w + 1u], u_vertex_words[w + 2u], u_vertex_words[w + 3u]));
}
vec2 vertex_vec2(uint v, uint word) {
  uint w = v * kVertexWords + word;
  return uintBitsToFloat(uvec2(u_vertex_words[w], u_vertex_words[w + 1u]));
}
vec4 vertex_color(uint v) {
  uint w = v * kVertexWords + 14u;
  return vec4(unpackUnorm2x16(u_vertex_words[w]), unpackUnorm2x16(u_vertex_words[w + 1u]));
}

// The world-space direction from the camera through `window` (pixels, GL's
// origin at the bottom left), aimed at the far plane (see gbuffer.glsl's view_ray).
vec3 window_ray(vec2 window) {
  vec2 ndc = window / u_viewport_size * 2.0 - 1.0;
  vec4 far_point = u_inverse_view_projection * vec4(ndc, kDepthFar, 1.0);
  return far_point.xyz / far_point.w - u_camera_position.xyz;
}

// Barycentrics (of p1 and p2; p0's is 1 minus both) where the ray from the
// camera along `d` meets the plane of the triangle (Moller-Trumbore, without
// the tests: a ray beside the triangle extrapolates, as a raster quad does).
vec2 ray_barycentrics(vec3 d, vec3 p0, vec3 e1, vec3 e2) {
  vec3 p = cross(d, e2);
  float inverse_det = 1.0 / dot(e1, p);
  vec3 t = u_camera_position.xyz - p0;
  return vec2(dot(t, p), dot(d, cross(t, e1))) * inverse_det;
}

#ifdef EXPLICIT_GRADIENTS
// Everything material evaluation needs at `pixel`, rebuilt from `triangle` of
// `instance` (visible_instance): fills the arguments of evaluate_material and
// g_uv_dx/g_uv_dy.
struct VisibleSurface {
  uint material;
  uint flags;
  vec3 position;
  vec3 normal;
  vec4 tangent;
  vec2 uv[5];
  vec4 color;
  bool front_facing;
};

VisibleSurface visible_surface(ivec2 pixel, Instance instance, uint triangle) {
  uint first = instance.material.z + 3u * triangle;
  int base_vertex = int(instance.material.w);
  uint v[3];
  vec3 world[3];
  for (int k = 0; k < 3; ++k) {
    v[k] = uint(int(u_index_pool[first + uint(k)]) + base_vertex);
    world[k] = (instance.model * vec4(vertex_vec3(v[k], 0u), 1.0)).xyz;
  }
  vec3 e1 = world[1] - world[0], e2 = world[2] - world[0];
  vec2 b = ray_barycentrics(window_ray(vec2(pixel) + 0.5), world[0], e1, e2);
  // The differences across the pixel's 2x2 quad, from its first pixel, as a
  // rasteriser's (coarse) derivatives take them: at a grazing angle forward
  // and backward differences pick different mip levels.
  vec2 quad = vec2(pixel & ~1) + 0.5;
  vec2 b0 = ray_barycentrics(window_ray(quad), world[0], e1, e2);
  vec2 bx = ray_barycentrics(window_ray(quad + vec2(1.0, 0.0)), world[0], e1, e2) - b0;
  vec2 by = ray_barycentrics(window_ray(quad + vec2(0.0, 1.0)), world[0], e1, e2) - b0;
  vec3 w = vec3(1.0 - b.x - b.y, b);
  vec3 wx = vec3(-bx.x - bx.y, bx);  // the weights' change to the next pixel right
  vec3 wy = vec3(-by.x - by.y, by);

  Material m = material_at(instance.material.x);
  VisibleSurface s;
  s.material = instance.material.x;
  s.flags = m.flags;
  s.position = world[0] + b.x * e1 + b.y * e2;
  vec3 normal = vec3(0.0);
  vec4 tangent = vec4(0.0);
  vec2 uv0[3], uv1[3];
  s.color = vec4(0.0);
  for (int k = 0; k < 3; ++k) {
    normal += w[k] * vertex_vec3(v[k], 3u);
    tangent += w[k] * vertex_vec4(v[k], 6u);
    uv0[k] = vertex_vec2(v[k], 10u);
    uv1[k] = vertex_vec2(v[k], 12u);
    s.color += w[k] * vertex_color(v[k]);
  }
  s.normal = mat3(instance.normal_matrix) * normal;
  // As mesh.vert: a mirroring model turns the bitangent's handedness.
  bool mirrored = determinant(mat3(instance.model)) < 0.0;
  s.tangent = vec4(mat3(instance.model) * tangent.xyz, mirrored ? -tangent.w : tangent.w);
  for (int slot = 0; slot < 5; ++slot) {
    bool second = (m.uv_sets & (1u << slot)) != 0u;
    vec2 a = second ? uv1[0] : uv0[0], c = second ? uv1[1] : uv0[1], d = second ? uv1[2] : uv0[2];
    vec2 uv = w.x * a + w.y * c + w.z * d;
    vec2 du_x = wx.x * a + wx.y * c + wx.z * d;
    vec2 du_y = wy.x * a + wy.y * c + wy.z * d;
    vec3 row0 = m.uv_transform[2 * slot].xyz, row1 = m.uv_transform[2 * slot + 1].xyz;
    s.uv[slot] = vec2(dot(row0, vec3(uv, 1.0)), dot(row1, vec3(uv, 1.0)));
    // Differences carry no translation.
    g_uv_dx[slot] = vec2(dot(row0.xy, du_x), dot(row1.xy, du_x));
    g_uv_dy[slot] = vec2(dot(row0.xy, du_y), dot(row1.xy, du_y));
  }
  // Counter-clockwise as the camera sees it is front-facing; a mirrored
  // instance is drawn with clockwise fronts (draw_items' glFrontFace).
  bool counter_clockwise = dot(cross(e1, e2), u_camera_position.xyz - world[0]) > 0.0;
  s.front_facing = counter_clockwise != mirrored;
  return s;
}
// Whether triangle surfaces `a` and `b`, rebuilt at the same pixel, feed the
// material and the lights the same inputs, within what the deferred modes'
// edge test lets pass (gbuffer_samples_differ): position within 0.1% of the
// distance, normals within about 2 degrees, tangents, colours and texture
// coordinates alike (the latter within 1% of a pixel's step, `texel_step`:
// texel_steps() of one of them). Two triangles of one flat or smooth surface
// meet this on the pixels their shared edge crosses.
bool same_surface(VisibleSurface a, VisibleSurface b, vec2 texel_step[5]) {
  if (a.material != b.material || a.front_facing != b.front_facing) return false;
  float range = length(a.position - u_camera_position.xyz);
  if (distance(a.position, b.position) > 1e-3 * range) return false;
  if (dot(normalize(a.normal), normalize(b.normal)) < 0.9995) return false;
  if (any(greaterThan(abs(a.tangent - b.tangent), vec4(0.02))) || any(greaterThan(abs(a.color - b.color), vec4(0.5 / 255.0)))) {
    return false;
  }
  for (int slot = 0; slot < 5; ++slot) {
    if (any(greaterThan(abs(a.uv[slot] - b.uv[slot]), 0.01 * texel_step[slot] + 1e-7))) return false;
  }
  return true;
}

// Each texture slot's UV step to the next pixel, of the surface visible_surface() rebuilt last.
void texel_steps(out vec2 texel_step[5]) {
  for (int slot = 0; slot < 5; ++slot) texel_step[slot] = abs(g_uv_dx[slot]) + abs(g_uv_dy[slot]);
}

// The surfaces that `pixel`'s samples (identifiers `ids`) show, each to be
// shaded once for all its samples: samples of one triangle always share,
// samples of different triangles when same_surface() holds. Only triangles of
// `material` count (kAnyMaterial: all). A group is named by its first sample
// (its leader): returns a bit per leader, and `group_of` gives each sample's
// leader in 4 bits (kNoGroup where the sample shows no triangle that counts).
//
// Only a pixel whose samples show two triangles or more rebuilds surfaces:
// each later triangle's once, and each earlier group's again for each
// comparison, rather than keeping them. An array of surfaces held in every
// invocation and indexed by a count lives in memory, not registers, on a GPU
// (the 4x resolve that kept one took 15 times the single-sample resolve on an
// H200), while ALU is plentiful there.
const uint kAnyMaterial = 0xffffffffu;
const uint kNoGroup = 0xfu;
#if defined(MSAA_SAMPLES) && MSAA_SAMPLES > 8
#error "surface_groups packs a sample's leader in 4 bits of 32: at most 8 samples"
#endif

uint group_at(uint group_of, int s) { return (group_of >> (4 * s)) & 0xfu; }
uint with_group(uint group_of, int s, uint leader) { return (group_of & ~(0xfu << (4 * s))) | (leader << (4 * s)); }
// The samples whose leader is `leader`.
uint group_mask(uint group_of, int leader) {
  uint mask = 0u;
  for (int s = 0; s < kSamples; ++s) mask |= group_at(group_of, s) == uint(leader) ? 1u << s : 0u;
  return mask;
}
// ids[s] through a constant index each (a chain of selects, not an array in memory).
uint id_at(uint ids[kSamples], int s) {
  uint id = ids[0];
  for (int k = 1; k < kSamples; ++k) id = k == s ? ids[k] : id;
  return id;
}

// The surface that sample `s` of `pixel` shows (identifiers `ids`).
VisibleSurface sample_surface(ivec2 pixel, uint ids[kSamples], int s) {
  uint triangle;
  Instance instance = visible_instance(id_at(ids, s), triangle);
  return visible_surface(pixel, instance, triangle);
}

// Moves the samples of group `from` to group `to` (kNoGroup: out of every group).
uint regroup(uint group_of, int from, uint to) {
  for (int s = from; s < kSamples; ++s) {
    if (group_at(group_of, s) == uint(from)) group_of = with_group(group_of, s, to);
  }
  return group_of;
}

uint surface_groups(ivec2 pixel, uint ids[kSamples], uint material, out uint group_of) {
  uint leaders = 0u;
  group_of = 0xffffffffu;  // kNoGroup everywhere
  for (int i = 0; i < kSamples; ++i) {
    if (ids[i] == 0u) continue;
    int earlier = i;
    for (int j = i - 1; j >= 0; --j) earlier = ids[j] == ids[i] ? j : earlier;
    group_of = with_group(group_of, i, uint(earlier));
    if (earlier == i) leaders |= 1u << i;
  }
  for (uint rest = material == kAnyMaterial ? 0u : leaders; rest != 0u; rest &= rest - 1u) {
    int leader = findLSB(rest);
    uint triangle;
    if (visible_instance(id_at(ids, leader), triangle).material.x == material) continue;
    group_of = regroup(group_of, leader, kNoGroup);
    leaders &= ~(1u << leader);
  }
  // Each later leader joins the first earlier group whose surface it shares.
  // The first group's surface is kept (in registers: one surface, not an
  // array), the others' rebuilt for each comparison.
  if ((leaders & (leaders - 1u)) == 0u) return leaders;
  int first_leader = findLSB(leaders);
  VisibleSurface first_surface = sample_surface(pixel, ids, first_leader);
  for (uint rest = leaders & (leaders - 1u); rest != 0u; rest &= rest - 1u) {
    int leader = findLSB(rest);
    VisibleSurface surface = sample_surface(pixel, ids, leader);
    vec2 texel_step[5];
    texel_steps(texel_step);
    int joined = same_surface(first_surface, surface, texel_step) ? first_leader : -1;
    for (uint before = leaders & ((1u << leader) - 1u) & ~(1u << first_leader); before != 0u && joined < 0; before &= before - 1u) {
      int other = findLSB(before);
      if (same_surface(sample_surface(pixel, ids, other), surface, texel_step)) joined = other;
    }
    if (joined < 0) continue;
    group_of = regroup(group_of, leader, uint(joined));
    leaders &= ~(1u << leader);
  }
  return leaders;
}
#endif
