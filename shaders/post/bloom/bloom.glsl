// Texel reads shared by the bloom chain's passes (src/render/post/bloom):
// every read is a texelFetch clamped to the image, so no pass depends on a
// sampler's filtering or wrap state, and the compute-free tier (WebGL2, ES
// 3.0) runs the same code.

// The average of the 2x2 texels that meet at corner `c` (texel i spans
// [i, i+1]): a bilinear sample taken exactly between four texels.
#define BLOOM_BOX(read, c) (0.25 * (read((c) + ivec2(-1, -1)) + read((c) + ivec2(0, -1)) + read((c) + ivec2(-1, 0)) + read(c)))

// A bilinear sample at `p` in texel units (texel i's centre at i + 0.5).
#define BLOOM_BILINEAR(read, p, result) { vec2 q_ = (p) - 0.5; ivec2 i_ = ivec2(floor(q_)); vec2 f_ = q_ - vec2(i_); result = mix(mix(read(i_), read(i_ + ivec2(1, 0)), f_.x), mix(read(i_ + ivec2(0, 1)), read(i_ + ivec2(1, 1)), f_.x), f_.y); }

float bloom_luma(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }
