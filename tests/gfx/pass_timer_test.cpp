// PassTimer's steps: each method times the steps a pass names (PassTimer::Step)
// inside it, in order; a step inside a step, or outside any pass, or with
// steps off, is not timed apart.
#include <cmath>

#include "gfx/gl_object.hpp"
#include "gfx/pass_timer.hpp"
#include "support/gl_test.hpp"

namespace atrium::gfx {
namespace {

using PassTimerTest = testing::GlTest;

// Some GPU work for a step to time: a buffer cleared.
void work(const Buffer& buffer) {
  const std::uint32_t value = 7;
  glClearNamedBufferData(buffer.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &value);
}

std::vector<PassTime> one_frame(PassTimer& timer, const Buffer& buffer) {
  timer.begin_frame();
  {
    const PassTimer::Step outside("outside");  // no pass is open: not timed
  }
  timer.begin_pass("pass");
  {
    const PassTimer::Step first("first");
    work(buffer);
    const PassTimer::Step inner("inner");  // inside "first": part of it
    work(buffer);
  }
  {
    const PassTimer::Step second("second");
    work(buffer);
  }
  timer.end_pass();
  timer.end_frame();
  timer.wait_for_latest();
  return timer.latest();
}

TEST_F(PassTimerTest, EachMethodTimesTheStepsAPassNamesInOrder) {
  Buffer buffer = create_buffer();
  glNamedBufferStorage(buffer.id(), 1 << 20, nullptr, 0);
  for (const TimingMethod method : {TimingMethod::GpuQueries, TimingMethod::CpuFinish}) {
    SCOPED_TRACE(method == TimingMethod::GpuQueries ? "queries" : "glFinish");
    PassTimer timer(method);
    EXPECT_FALSE(timer.times_steps()) << "off by default";
    std::vector<PassTime> passes = one_frame(timer, buffer);
    ASSERT_EQ(passes.size(), 1u);
    EXPECT_TRUE(passes[0].steps.empty());

    timer.time_steps(true);
    passes = one_frame(timer, buffer);
    ASSERT_EQ(passes.size(), 1u);
    ASSERT_EQ(passes[0].steps.size(), 2u);
    EXPECT_EQ(passes[0].steps[0].name, "first");
    EXPECT_EQ(passes[0].steps[1].name, "second");
    for (const StepTime& step : passes[0].steps) {
      EXPECT_TRUE(std::isfinite(step.milliseconds) && step.milliseconds >= 0.0) << step.name << ": " << step.milliseconds;
    }
    // The same names again next frame: the queries are reused, not grown.
    passes = one_frame(timer, buffer);
    ASSERT_EQ(passes[0].steps.size(), 2u);
    EXPECT_EQ(passes[0].steps[1].name, "second");
  }
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

}  // namespace
}  // namespace atrium::gfx
