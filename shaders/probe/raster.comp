#version 450 core
// Raster probe, compute side (gfx/stage_probe.hpp): one invocation rasterises
// one small triangle, as Nanite's software rasteriser does, into a storage
// buffer of a texel per pixel by atomicMax: Atrium's depth is reversed
// (gfx/depth.hpp, nearer is larger), and a positive float's bits order as the
// float does. With IDENTIFIERS (64-bit atomics, NV_shader_atomic_int64) a
// texel holds the depth's bits over the triangle's index, the visibility
// buffer's content; without, the depth alone. Coverage follows the raster
// pipeline's rules: vertices snapped to 1/256 pixel, pixel centres tested,
// ties to top and left edges. Edge values are 32-bit: triangles up to about
// 100 pixels a side.
#ifdef IDENTIFIERS
#extension GL_ARB_gpu_shader_int64 : require
#extension GL_NV_shader_atomic_int64 : require
#endif
layout(local_size_x = 64) in;

layout(std430, binding = 0) readonly buffer Positions { float positions[]; };  // clip-space xyz a vertex, w = 1
layout(std430, binding = 1) readonly buffer Indices { uint indices[]; };
#ifdef IDENTIFIERS
layout(std430, binding = 2) buffer Target { uint64_t texels[]; };
#else
layout(std430, binding = 2) buffer Target { uint texels[]; };
#endif

uniform uint u_triangles;
uniform ivec2 u_size;

int edge(ivec2 a, ivec2 b, ivec2 p) {
  return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

// Counter-clockwise (y up): the interior lies left of each edge. A pixel
// centre on an edge belongs to the triangle if that edge is a top edge
// (horizontal, going left) or a left edge (going down).
bool owns_ties(ivec2 a, ivec2 b) {
  ivec2 d = b - a;
  return d.y < 0 || (d.y == 0 && d.x < 0);
}

void main() {
  uint t = gl_GlobalInvocationID.x;
  if (t >= u_triangles) return;
  ivec2 v[3];
  float z[3];
  for (int k = 0; k < 3; ++k) {
    uint i = indices[3u * t + uint(k)];
    vec3 ndc = vec3(positions[3u * i], positions[3u * i + 1u], positions[3u * i + 2u]);
    v[k] = ivec2(round((ndc.xy * 0.5 + 0.5) * vec2(u_size) * 256.0));
    z[k] = ndc.z;  // clip-space z is the depth (glClipControl's GL_ZERO_TO_ONE, or clip.glsl's remap)
  }
  int area = edge(v[0], v[1], v[2]);
  if (area == 0) return;
  if (area < 0) {
    ivec2 swap_v = v[1]; v[1] = v[2]; v[2] = swap_v;
    float swap_z = z[1]; z[1] = z[2]; z[2] = swap_z;
    area = -area;
  }
  // The pixels whose centres (p * 256 + 128) the box holds, inside the image.
  ivec2 lo = max(ivec2(ceil((vec2(min(min(v[0], v[1]), v[2])) - 128.0) / 256.0)), ivec2(0));
  ivec2 hi = min(ivec2(floor((vec2(max(max(v[0], v[1]), v[2])) - 128.0) / 256.0)), u_size - 1);
  bool tie0 = owns_ties(v[1], v[2]), tie1 = owns_ties(v[2], v[0]), tie2 = owns_ties(v[0], v[1]);
  for (int y = lo.y; y <= hi.y; ++y) {
    for (int x = lo.x; x <= hi.x; ++x) {
      ivec2 p = ivec2(x, y) * 256 + 128;
      int w0 = edge(v[1], v[2], p), w1 = edge(v[2], v[0], p), w2 = edge(v[0], v[1], p);
      if (w0 < 0 || w1 < 0 || w2 < 0) continue;
      if ((w0 == 0 && !tie0) || (w1 == 0 && !tie1) || (w2 == 0 && !tie2)) continue;
      float depth = (float(w0) * z[0] + float(w1) * z[1] + float(w2) * z[2]) / float(area);
      uint index = uint(y * u_size.x + x);
#ifdef IDENTIFIERS
      atomicMax(texels[index], uint64_t(floatBitsToUint(depth)) << 32 | uint64_t(t));
#else
      atomicMax(texels[index], floatBitsToUint(depth));
#endif
    }
  }
}
