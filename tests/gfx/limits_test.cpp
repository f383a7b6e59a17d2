// What the context allows: the loop limit Atrium assumes is the one the driver
// really applies (measured with a compute shader), the render size limit is
// usable, the proxy tells what texture the context can hold, and memory
// figures print the way refusal messages quote them.
#include <cstdio>

#include <gmock/gmock.h>

#include "base/format.hpp"
#include "base/mip_levels.hpp"
#include "gfx/limits.hpp"
#include "support/compute_probe.hpp"
#include "support/gl_test.hpp"

namespace atrium::gfx {
namespace {

using Limits = testing::GlTest;

// Runs `body` (GLSL that returns a uint from `uint n`) with the same n in every
// invocation: llvmpipe counts a loop's iterations per SIMD vector, so lanes with
// different trip counts would share one budget.
std::uint32_t run_loops(const std::string& body, std::uint32_t n) {
  const std::string includes = "uint iterations(uint n) {\n" + body + "\n}\n";
  return testing::evaluate_glsl<std::uint32_t>(includes, "uint", "uint", "iterations(value)", std::vector<std::uint32_t>(64, n))[0];
}

TEST_F(Limits, TheLoopLimitIsTheOneTheDriverApplies) {
  // Each iteration feeds the next, so the compiler cannot replace a loop by its trip count.
  const std::string one_loop =
      "uint done = 0u, state = n;\n"
      "for (uint i = 0u; i < n; ++i) { state = state * 1664525u + 1013904223u; done += 1u | (state & 0u); }\n"
      "return done + (state & 0u);";
  const std::string two_loops =
      "uint done = 0u, state = n;\n"
      "for (uint i = 0u; i < n; ++i) { state = state * 1664525u + 1013904223u; done += 1u | (state & 0u); }\n"
      "for (uint i = 0u; i < n; ++i) { state = state * 22695477u + 1u; done += 1u | (state & 0u); }\n"
      "return done + (state & 0u);";
  const std::uint32_t limit = shader_loop_limit();
  EXPECT_EQ(run_loops(one_loop, 1000), 1000u);
  EXPECT_EQ(run_loops(one_loop, 100000), limit ? limit : 100000u) << "assumed limit " << limit;
  const std::uint32_t both = run_loops(two_loops, 40000);
  if (limit) {
    // The budget is the shader's, not each loop's: 80,000 iterations asked for,
    // about the limit run (give or take the iteration in which it runs out).
    EXPECT_NEAR(static_cast<double>(both), static_cast<double>(limit), 2.0) << "assumed limit " << limit;
  } else {
    EXPECT_EQ(both, 80000u);
  }
}

TEST_F(Limits, RenderAndTextureSizesAreUsable) {
  EXPECT_GE(max_texture_size(), 16384) << "OpenGL 4.5 guarantees 16384";
  const glm::ivec2 render = max_render_size();
  EXPECT_GE(render.x, 8192);
  EXPECT_GE(render.y, 8192);
  EXPECT_LE(render.x, max_texture_size());
  EXPECT_GE(storage_block_limit(), std::uint64_t{1} << 24) << "OpenGL 4.3 and later guarantee 16 MiB";
}

// The proxy answers without raising an error: yes for a small texture, no
// past GL_MAX_TEXTURE_SIZE, and for the most memory a 2D texture can ask
// (16384 x 16384 RGBA32F with its mips, 5.3 GiB) whatever the driver holds.
TEST_F(Limits, TheProxyTellsWhatTextureTheContextCanHoldWithoutAnError) {
  EXPECT_TRUE(texture_fits(GL_RGBA8, 7, {64, 64}));
  EXPECT_TRUE(texture_fits(GL_SRGB8_ALPHA8, 1, {max_texture_size(), 1}));
  EXPECT_FALSE(texture_fits(GL_RGBA8, 1, {max_texture_size() * 2, 1}));
  const int most = max_texture_size();
  std::printf("%dx%d RGBA32F with its mips: %s\n", most, most,
              texture_fits(GL_RGBA32F, mip_levels(most, most), {most, most}) ? "held" : "refused");
}

TEST(FormatBytes, PicksTheUnitAUserReads) {
  EXPECT_EQ(format_bytes(0), "0 bytes");
  EXPECT_EQ(format_bytes(1023), "1023 bytes");
  EXPECT_EQ(format_bytes(12 * 1024), "12.0 KiB");
  EXPECT_EQ(format_bytes(813'088'000), "775.4 MiB");
  EXPECT_EQ(format_bytes(static_cast<double>(std::uint64_t{3} << 29)), "1.5 GiB");
  EXPECT_EQ(with_commas(4'000'000'000), "4,000,000,000");
}

}  // namespace
}  // namespace atrium::gfx
