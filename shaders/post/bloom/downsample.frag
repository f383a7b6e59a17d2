#version 450 core
// A level of the bloom chain as a full-screen pass over it (downsample.glsl).
#include "post/bloom/downsample.glsl"

layout(location = 0) out vec4 out_color;

void main() { out_color = vec4(bloom_downsample(ivec2(gl_FragCoord.xy)), 1.0); }
