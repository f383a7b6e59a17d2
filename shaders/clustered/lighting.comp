#version 450 core
// Clustered deferred lighting as a compute pass, one invocation per pixel (clustered/lighting.glsl).
#define COMPUTE_STAGE
#include "clustered/lighting.glsl"
