// What common/mesh.vert hands every fragment shader of a mesh pass, declared
// once so that all passes interpolate alike: at the pixel centre, also with
// MSAA, where a silhouette pixel's centre may lie off the triangle and the
// values are extrapolated. Centroid sampling would keep them on the surface,
// but the compact and thin G-buffers rebuild a position from the distance
// along the pixel's centre ray, which only a centre-sampled position survives
// exactly; the tiled and clustered modes bin lights from the positions shading
// reads (the G-buffer, or the pre-pass's shading depth) for the same reason.
in vec3 v_position;
in vec3 v_normal;
in vec4 v_tangent;
in vec2 v_uv[5];
in vec4 v_color;
