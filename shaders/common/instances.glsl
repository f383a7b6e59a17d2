// The frame's instance records: one per primitive instance drawn (its
// meshlets' draws share it), read by common/mesh.vert through the
// instance-slot attribute and by the visibility buffer's resolve through its
// unit table.
// C++ twin: InstanceData in src/render/frame/draw_list.hpp.
struct Instance {
  mat4 model;
  mat4 normal_matrix;  // the inverse transpose in the upper-left 3x3
  // x: index into the frame's material table (material_data.glsl); y: the
  // visibility identifier of the primitive's first triangle; z, w: its
  // first index and base vertex in the geometry pools.
  uvec4 material;
};
#ifdef NO_STORAGE_BUFFERS
// The compute-free tier: the records in a texture, 9 RGBA32F texels each,
// kInstancesPerRow a row (C++ twin: kInstanceTexels and kInstancesPerRow in
// src/render/storage_free.hpp).
layout(binding = 11) uniform highp sampler2D u_instance_texture;

const uint kInstancesPerRow = 227u;  // 2,043 texels: within WebGL2's least texture width, 2,048

Instance instance_at(uint i) {
  ivec2 row = ivec2(int(i % kInstancesPerRow) * 9, int(i / kInstancesPerRow));
  Instance instance;
  for (int c = 0; c < 4; ++c) {
    instance.model[c] = texelFetch(u_instance_texture, row + ivec2(c, 0), 0);
    instance.normal_matrix[c] = texelFetch(u_instance_texture, row + ivec2(4 + c, 0), 0);
  }
  // Whole numbers stored as floats; the tier reads only x (no visibility buffer there).
  instance.material = uvec4(texelFetch(u_instance_texture, row + ivec2(8, 0), 0));
  return instance;
}
#else
layout(std430, binding = 1) readonly buffer Instances { Instance u_instances[]; };

Instance instance_at(uint i) { return u_instances[i]; }
#endif

