#version 450 core
// Clustered deferred lighting as a full-screen fragment pass (clustered/lighting.glsl).
#include "clustered/lighting.glsl"
