// FramePacer holds a frame loop at most kFramesInFlight frames ahead of the
// GPU: when a frame begins, everything submitted before the end of the frame
// kFramesInFlight before it has run, and the wait for that is not counted as a
// GPU wait (gfx/gpu_waits.hpp): it falls between frames, with one still queued.
#include "gfx/frame_pacer.hpp"

#include <deque>

#include "gfx/gpu_waits.hpp"
#include "support/gl_test.hpp"

namespace atrium::gfx {
namespace {

using FramePacerTest = testing::GlTest;

TEST_F(FramePacerTest, AFrameBeginsOnceTheFrameTwoBeforeItHasRun) {
  static_assert(FramePacer::kFramesInFlight == 2);
  // A frame's work: a 64 MiB target cleared, which llvmpipe's rasteriser
  // threads do after the flush, while the CPU goes on.
  Texture target = create_texture(GL_TEXTURE_2D);
  glTextureStorage2D(target.id(), 1, GL_RGBA32F, 2048, 2048);
  Framebuffer framebuffer = create_framebuffer();
  glNamedFramebufferTexture(framebuffer.id(), GL_COLOR_ATTACHMENT0, target.id(), 0);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
  glViewport(0, 0, 2048, 2048);

  FramePacer pacer;
  std::deque<Fence> before_end;  // placed just before each of the last frames ended, oldest first
  for (int frame = 0; frame < 8; ++frame) {
    const std::uint64_t waits = gpu_waits();
    pacer.begin_frame();
    EXPECT_EQ(gpu_waits(), waits) << "frame " << frame << ": the pacer's wait is not a stall";
    EXPECT_GE(pacer.waited_ms(), 0.0);
    if (before_end.size() == FramePacer::kFramesInFlight) {
      EXPECT_FALSE(before_end.front().wait_uncounted()) << "frame " << frame << " began before the GPU ran the frame two before it";
      before_end.pop_front();
    }
    const float colour[4] = {static_cast<float>(frame), 0.0f, 0.0f, 1.0f};
    glClearBufferfv(GL_COLOR, 0, colour);
    before_end.emplace_back().place();
    pacer.end_frame();
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

}  // namespace
}  // namespace atrium::gfx
