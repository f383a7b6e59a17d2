#version 450 core
// Tiled deferred lighting as a compute pass, one invocation per pixel (tiled/lighting.glsl).
#define COMPUTE_STAGE
#include "tiled/lighting.glsl"
