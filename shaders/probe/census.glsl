// Shared by the stage probe's compute and fragment shaders (gfx/stage_probe.hpp):
// the arithmetic both stages time, and the count of invocations per SM. It is
// included first: the extension must come before any other token.
#ifdef HAS_SM_ID
#extension GL_NV_shader_thread_group : require
#endif

layout(std430, binding = 0) buffer Census {
  uint invocations_per_sm[256];
};

uniform uint u_iterations;
uniform bool u_census;

// Eight independent chains of multiply-adds (two flops each) per iteration:
// enough independent work to fill an SM's pipes, kept alive by the output.
float arithmetic(vec2 seed) {
  float a = seed.x, b = seed.y, c = a + 1.0, d = b + 1.0, e = a * 0.5, f = b * 0.5, g = a - 1.0, h = b - 1.0;
  for (uint i = 0u; i < u_iterations; ++i) {
    a = fma(a, 0.9999, 0.0001); b = fma(b, 0.9998, 0.0002); c = fma(c, 0.9997, 0.0003); d = fma(d, 0.9996, 0.0004);
    e = fma(e, 0.9995, 0.0005); f = fma(f, 0.9994, 0.0006); g = fma(g, 0.9993, 0.0007); h = fma(h, 0.9992, 0.0008);
  }
  return a + b + c + d + e + f + g + h;
}

// One count per invocation on the SM that ran it (the census pass only).
void count_invocation() {
#ifdef HAS_SM_ID
  if (u_census) atomicAdd(invocations_per_sm[min(gl_SMIDNV, 255u)], 1u);
#endif
}
