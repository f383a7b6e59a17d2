// GL test support: one headless debug context for the whole test program, and
// a fixture that fails any test during which the driver reported a GL error.
#pragma once

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include "gfx/debug_output.hpp"

namespace atrium::testing {

// The size picture tests render at unless they need another: small enough
// for llvmpipe, large enough to see the scene (the README's smallest test size).
inline constexpr glm::ivec2 kSize{160, 90};

class GlTest : public ::testing::Test {
 protected:
  void SetUp() override { gfx::reset_gl_error_count(); }
  void TearDown() override {
    EXPECT_EQ(gfx::gl_error_count(), 0u) << "GL error reported through KHR_debug: " << gfx::last_gl_error();
  }
};

}  // namespace atrium::testing
