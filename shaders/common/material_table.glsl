// The frame's material table: one entry per material drawn this frame, indexed
// by the instance records (mesh.vert). Bound at kMaterialStorageBinding
// (src/render/frame/draw_list.hpp), or on the compute-free tier (no storage
// buffers) as a texture of kMaterialTexels RGBA32F texels per material,
// kMaterialsPerRow a row (C++ twins in src/render/storage_free.hpp).
#include "material_data.glsl"

#ifdef NO_STORAGE_BUFFERS
const int kMaterialTexels = 14;
const uint kMaterialsPerRow = 146u;  // 2,044 texels: within WebGL2's least texture width, 2,048
layout(binding = 12) uniform highp sampler2D u_material_texture;

Material material_at(uint i) {
  Material m;
  vec4 t[kMaterialTexels];
  ivec2 first = ivec2(int(i % kMaterialsPerRow) * kMaterialTexels, int(i / kMaterialsPerRow));
  for (int k = 0; k < kMaterialTexels; ++k) t[k] = texelFetch(u_material_texture, first + ivec2(k, 0), 0);
  m.base_color_factor = t[0];
  m.emissive = t[1];
  m.metallic_factor = t[2].x;
  m.roughness_factor = t[2].y;
  m.occlusion_strength = t[2].z;
  m.alpha_cutoff = t[2].w;
  m.flags = uint(t[3].x);  // whole numbers stored as floats: exact, and never a denormal a GPU may flush
  m.uv_sets = uint(t[3].y);
  m.padding0 = 0u;
  m.padding1 = 0u;
  for (int k = 0; k < 10; ++k) m.uv_transform[k] = t[4 + k];
  return m;
}
#else
layout(std430, binding = 8) readonly buffer Materials { Material u_materials[]; };

Material material_at(uint i) { return u_materials[i]; }
#endif
