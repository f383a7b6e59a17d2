#version 450 core
// Deferred lighting as a compute pass, one invocation per pixel (deferred/lighting.glsl).
#define COMPUTE_STAGE
#include "deferred/lighting.glsl"
