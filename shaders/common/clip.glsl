// Vertex shaders end with clip_position(): Atrium's depth convention
// (gfx/depth.hpp) has clip-space z in [0, w], near at w, through glClipControl.
// A context without it (OpenGL 4.1, ES 3.0, WebGL2) clips z to [-w, w] and
// writes (z/w + 1) / 2: CLIP_Z_MINUS_ONE_TO_ONE maps one range onto the other,
// so the depth buffer holds the same values there (less precisely far away).
vec4 clip_position(vec4 p) {
#ifdef CLIP_Z_MINUS_ONE_TO_ONE
  p.z = 2.0 * p.z - p.w;
#endif
  return p;
}

// Light volumes need depth clamp (a sphere that crosses the near or far plane
// stays whole). Without GL_DEPTH_CLAMP (ES 3.0, WebGL2) each vertex's depth is
// clamped into the clip volume instead; vertices behind the camera are left to
// clipping.
vec4 depth_clamped(vec4 p) {
#ifdef NO_DEPTH_CLAMP
  if (p.w > 0.0) p.z = clamp(p.z, 0.0, p.w);
#endif
  return p;
}
