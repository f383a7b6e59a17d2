#version 450 core
// A level of the bloom chain on the way up, as a full-screen pass over it (upsample.glsl).
#include "post/bloom/upsample.glsl"

layout(location = 0) out vec4 out_color;

void main() { out_color = vec4(bloom_upsample(ivec2(gl_FragCoord.xy)), 1.0); }
