#version 450 core
// Stage probe, fragment side: a full-screen triangle whose fragments run the
// probe's arithmetic into an R32F target (gfx/stage_probe.hpp), the same work
// per pixel as the compute side.
#include "probe/census.glsl"

out float o_value;

void main() {
  count_invocation();
  o_value = arithmetic(floor(gl_FragCoord.xy) * 1e-3);
}
