#version 450 core
// Deferred lighting as a full-screen fragment pass (deferred/lighting.glsl).
#include "deferred/lighting.glsl"
