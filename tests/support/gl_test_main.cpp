// main() for GL test programs: creates the headless context (with KHR_debug
// output) before any test runs and destroys it after the last.
#include <cstdio>
#include <memory>

#include <gtest/gtest.h>

#include "gfx/context.hpp"

namespace {
class GlEnvironment : public ::testing::Environment {
 public:
  void SetUp() override {
    context_ = atrium::gfx::HeadlessContext::create(atrium::gfx::ContextOptions{.debug = true});
    std::printf("GL context: %s, %s (%s)\n", context_->info().renderer.c_str(), context_->info().version.c_str(),
                context_->info().platform.c_str());
  }
  void TearDown() override { context_.reset(); }

 private:
  std::unique_ptr<atrium::gfx::HeadlessContext> context_;
};
}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ::testing::AddGlobalTestEnvironment(new GlEnvironment);
  return RUN_ALL_TESTS();
}
