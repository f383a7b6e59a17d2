// The frame's material table: one entry per material drawn this frame, indexed
// by the instance records (mesh.vert). Bound at kMaterialStorageBinding
// (src/render/frame/draw_list.hpp).
#include "material_data.glsl"

layout(std430, binding = 8) readonly buffer Materials { Material u_materials[]; };
