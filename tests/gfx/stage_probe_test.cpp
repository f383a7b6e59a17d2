// The stage probe (`atrium probe`): both stages run and are timed over the
// same pixels, and a driver without NVIDIA's SM ids reports no SM counts
// rather than made-up ones.
#include <gmock/gmock.h>

#include "gfx/gl_features.hpp"
#include "gfx/stage_probe.hpp"
#include "support/gl_test.hpp"

namespace atrium::gfx {
namespace {

using StageProbe = testing::GlTest;

TEST_F(StageProbe, TimesTheSameWorkInBothStages) {
  const StageProbeResult result = run_stage_probe({64, 48}, 16, 3);
  EXPECT_EQ(result.size, glm::ivec2(64, 48));
  EXPECT_EQ(result.runs, 3u);
  EXPECT_DOUBLE_EQ(result.flops(), 64.0 * 48.0 * 16.0 * 16.0);
  EXPECT_GT(result.compute.milliseconds, 0.0);
  EXPECT_GT(result.fragment.milliseconds, 0.0);
  EXPECT_FALSE(result.timing.empty());
}

TEST_F(StageProbe, CountsSmsOnlyWhereTheDriverNamesThem) {
  const StageProbeResult result = run_stage_probe({32, 32}, 1, 1);
  if (!result.sm_ids) {
    EXPECT_EQ(result.sm_count, 0u);
    EXPECT_EQ(result.compute.sms_reached(), 0u);
    EXPECT_TRUE(result.fragment.invocations.empty());
    return;
  }
  // Every invocation is counted once, on an SM the driver says exists.
  for (const StageReach* reach : {&result.compute, &result.fragment}) {
    std::uint64_t total = 0;
    for (std::uint32_t n : reach->invocations) total += n;
    EXPECT_EQ(total, 32u * 32u);
    EXPECT_LE(reach->invocations.size(), result.sm_count);
    EXPECT_GE(reach->sms_reached(), 1u);
  }
}

}  // namespace
}  // namespace atrium::gfx
