#version 450 core
// Tiled deferred lighting as a full-screen fragment pass (tiled/lighting.glsl).
#include "tiled/lighting.glsl"
