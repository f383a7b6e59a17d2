// Where the GPU runs each shader stage, and what that costs: one pass of
// arithmetic per pixel run as a compute dispatch and as a full-screen fragment
// pass, each counted per SM (NVIDIA's GL_NV_shader_thread_group: gl_SMIDNV,
// GL_SM_COUNT_NV, where the driver has it) and timed. It exists because a
// Hopper GPU runs fragment shaders on few of its SMs and compute on all of them
// (docs/benchmarks.md): `atrium probe` measures that instead of assuming it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace atrium::gfx {

struct StageReach {
  double milliseconds = 0;                  // the timed pass, median of the runs
  std::vector<std::uint32_t> invocations;   // the census pass's invocations per SM id; empty without SM ids
  // SMs that ran at least one invocation; 0 without SM ids.
  [[nodiscard]] std::uint32_t sms_reached() const;
};

struct StageProbeResult {
  glm::ivec2 size{0};
  std::uint32_t iterations = 0;          // loop iterations per pixel, 16 flops each
  std::uint32_t runs = 0;                // timed runs per stage
  bool sm_ids = false;                   // GL_NV_shader_thread_group is present
  std::uint32_t sm_count = 0;            // GL_SM_COUNT_NV (0 without the extension)
  std::uint32_t warp_size = 0, warps_per_sm = 0;
  std::string timing;                    // how passes were timed (PassTimer::method_name)
  StageReach compute, fragment;
  // Floating-point operations the timed pass does (pixels x iterations x 16).
  [[nodiscard]] double flops() const;
};

// Runs the probe on the current context, which must have compute shaders and
// storage buffers (throws std::runtime_error naming what is missing).
[[nodiscard]] StageProbeResult run_stage_probe(glm::ivec2 size, std::uint32_t iterations = 256, std::uint32_t runs = 5);

}  // namespace atrium::gfx
