#version 450 core
// Reads the frame's indirect commands as the CPU wrote them (everything in
// view, one per primitive or meshlet), their boxes and the depth pyramid;
// writes the commands each occlusion-culling phase draws, with the instance
// count of what it leaves out set to 0, and which units the next frame draws
// first. The GPU twin of render/culling/occlusion_culling.cpp: nothing is read back.
//   u_phase 0 (before the first pass):  u_out = what the last frame showed
//   u_phase 1 (after its depth):        u_out = what that depth does not hide
//                                       and was not drawn; u_shown = both;
//                                       u_last_shown = what that depth does not hide
//   u_phase 2 (camera cuts only, after the second draw):
//                                       u_last_shown = what the full depth does not hide
// One pyramid a frame: the next frame's first draws come from the same test
// (as Niagara's late pass does), not from a second pyramid of the full depth.
// That depth lacks only what the second draw adds, so it keeps a unit that
// the revealed ones hide for one more frame, and never drops a shown one.
// After a camera cut the first depth is what the last view chose and hides
// little, so phase 2 chooses from the full one.
layout(local_size_x = 64) in;

#include "common/frame.glsl"

// GL's DrawElementsIndirectCommand (DrawCommand in src/render/frame/draw_list.hpp).
struct DrawCommand {
  uint count;
  uint instance_count;
  uint first_index;
  int base_vertex;
  uint base_instance;
};

// C++ twin: CullRecord in src/render/frame/draw_list.hpp.
struct CullRecord {
  vec4 box_min;
  vec4 box_max;
  uint unit;
  uint triangles;
  uint padding0;
  uint padding1;
};
const uint kNeverCulled = 0xffffffffu;

layout(std430, binding = 10) readonly buffer Pyramid { float u_pyramid[]; };
layout(std430, binding = 16) readonly buffer Template { DrawCommand u_template[]; };
layout(std430, binding = 17) writeonly buffer Out { DrawCommand u_out[]; };
layout(std430, binding = 18) writeonly buffer Shown { DrawCommand u_shown[]; };
layout(std430, binding = 19) readonly buffer Records { CullRecord u_records[]; };
layout(std430, binding = 20) buffer LastShown { uint u_last_shown[]; };
// [0]: triangles the passes after the first draw, [1]: triangles in view that no pass draws.
layout(std430, binding = 21) buffer Counters { uint u_counters[]; };

uniform uint u_phase;
uniform uint u_command_count;
uniform uint u_opaque_count;  // commands [0, u_opaque_count) have records; the rest are blended, never culled
uniform int u_level_count;
uniform ivec4 u_levels[16];   // per pyramid level: xy its size in texels, z its first texel's offset

const int kTileSize = 8;  // pixels per finest texel (depth_tiles.comp's work group)

// Whether the world-space box lies behind the pyramid's depth over every pixel
// it covers; the same steps as DepthPyramid::hides.
bool hides(vec3 box_min, vec3 box_max) {
  if (u_level_count == 0) return false;
  vec2 low = vec2(3.4e38), high = vec2(-3.4e38);
  float nearest = 3.4e38;
  for (int corner = 0; corner < 8; ++corner) {
    vec4 world = vec4((corner & 1) != 0 ? box_max.x : box_min.x, (corner & 2) != 0 ? box_max.y : box_min.y,
                      (corner & 4) != 0 ? box_max.z : box_min.z, 1.0);
    vec4 eye = u_view * world;
    float depth = -eye.z;
    if (!(depth > u_near)) return false;
    vec4 clip = u_projection * eye;
    vec2 ndc = clip.xy / clip.w;
    low = min(low, ndc);
    high = max(high, ndc);
    nearest = min(nearest, depth);
  }
  vec2 viewport = u_viewport_size;
  vec2 pixels_low = (low * 0.5 + 0.5) * viewport;
  vec2 pixels_high = (high * 0.5 + 0.5) * viewport;
  if (!(pixels_low.x < viewport.x && pixels_low.y < viewport.y && pixels_high.x > 0.0 && pixels_high.y > 0.0)) return false;
  ivec2 last_tile = u_levels[0].xy - 1;
  ivec2 first = clamp(ivec2(floor(pixels_low / float(kTileSize))), ivec2(0), last_tile);
  ivec2 last = clamp(ivec2(floor(pixels_high / float(kTileSize))), ivec2(0), last_tile);
  int level = 0;
  while (level + 1 < u_level_count && (last.x - first.x > 1 || last.y - first.y > 1)) {
    first /= 2;
    last /= 2;
    ++level;
  }
  float farthest = 0.0;
  for (int y = first.y; y <= last.y; ++y) {
    for (int x = first.x; x <= last.x; ++x) farthest = max(farthest, u_pyramid[u_levels[level].z + y * u_levels[level].x + x]);
  }
  return nearest > farthest * 1.001;
}

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= u_command_count) return;
  DrawCommand command = u_template[i];
  bool opaque = i < u_opaque_count;
  CullRecord record;
  bool shown_before = true;  // drawn by the first phase
  if (opaque) {
    record = u_records[i];
    shown_before = record.unit == kNeverCulled || u_last_shown[record.unit] != 0u;
  }
  if (u_phase == 0u) {
    command.instance_count = shown_before ? 1u : 0u;
    u_out[i] = command;
  } else {
    // Every opaque unit is tested, the ones drawn first too: what that depth
    // hides is not drawn first next frame. shown_before was read above, so
    // this invocation, the unit's only one, may write its bit now.
    bool tested = opaque && record.unit != kNeverCulled;
    bool hidden = tested && hides(record.box_min.xyz, record.box_max.xyz);
    if (tested) u_last_shown[record.unit] = hidden ? 0u : 1u;
    // A cut's second test chooses only what the next frame draws first.
    if (u_phase == 2u) return;
    // Blended commands: drawn by the passes after the first, not by this one.
    bool shown = !opaque || shown_before || !hidden;
    DrawCommand late = command;
    late.instance_count = opaque && shown && !shown_before ? 1u : 0u;
    u_out[i] = late;
    command.instance_count = shown ? 1u : 0u;
    u_shown[i] = command;
    if (opaque) atomicAdd(u_counters[shown ? 0 : 1], record.triangles);
  }
}
