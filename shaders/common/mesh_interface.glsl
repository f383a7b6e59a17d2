// What common/mesh.vert hands the fragment shader of every mesh pass, declared
// once for both stages (mesh.vert defines MESH_VERTEX_STAGE before including
// it), each value at a location of its own: the two stages meet where this
// file says, whatever else each declares and in what order, and no driver's
// packing of names decides it. ES 3.00 takes the locations out and matches by
// name (gfx/glsl_dialect.hpp).
//
// Interpolation is at the pixel centre, also with MSAA, where a silhouette
// pixel's centre may lie off the triangle and the values are extrapolated.
// Centroid sampling would keep them on the surface, but the compact and thin
// G-buffers rebuild a position from the distance along the pixel's centre ray,
// which only a centre-sampled position survives exactly; the tiled and
// clustered modes bin lights from the positions shading reads (the G-buffer, or
// the pre-pass's shading depth) for the same reason.
#ifdef MESH_VERTEX_STAGE
#define MESH_VARYING out
#else
#define MESH_VARYING in
#endif

#ifdef VISIBILITY_ID
// The identifier of the draw's first triangle (visibility/id.frag adds gl_PrimitiveID).
layout(location = 0) flat MESH_VARYING uint v_first_triangle_id;
#endif
#ifndef POSITION_ONLY
layout(location = 1) MESH_VARYING vec3 v_position;
layout(location = 2) MESH_VARYING vec3 v_normal;
layout(location = 3) MESH_VARYING vec4 v_tangent;
// Per material texture slot (base colour, metallic-roughness, normal,
// occlusion, emissive): the UV set it reads through its KHR_texture_transform,
// one location each (4-8).
layout(location = 4) MESH_VARYING vec2 v_uv[5];
layout(location = 9) MESH_VARYING vec4 v_color;
// The instance's material and its Material.flags, flat: fragment shaders
// branch on values that agree across a pixel quad.
layout(location = 10) flat MESH_VARYING uint v_material;
layout(location = 11) flat MESH_VARYING uint v_material_flags;
#endif
