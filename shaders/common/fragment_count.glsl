// The fragments debug view compiles every shader that rasterises scene
// geometry with COUNT_FRAGMENTS: each invocation adds one to its pixel before
// any discard. Writing memory keeps the depth test after the shader, so every
// fragment the rasteriser produces is counted: the overdraw a pass would shade
// without early depth tests (image unit 1; the heatmap uses unit 0). Shadow
// passes (SHADOW_PASS) draw into atlas tiles, not the camera's pixels: not counted.
#if defined(COUNT_FRAGMENTS) && !defined(SHADOW_PASS)
layout(r32ui, binding = 1) uniform coherent uimage2D u_fragment_counts;
void count_fragment() { imageAtomicAdd(u_fragment_counts, ivec2(gl_FragCoord.xy), 1u); }
#else
void count_fragment() {}
#endif
