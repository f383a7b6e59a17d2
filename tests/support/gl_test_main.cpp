// main() for GL test programs: creates the headless context (with KHR_debug
// output, and buffers poisoned as they are made: gfx/allocation_poison.hpp)
// before any test runs and destroys it after the last.
// $ATRIUM_TEST_GL (auto, 4.5, 4.1, es3.0; as --gl) picks the API it asks for.
#include <cstdio>
#include <cstdlib>
#include <memory>

#include <gtest/gtest.h>

#include "gfx/allocation_poison.hpp"
#include "gfx/context.hpp"

namespace {
class GlEnvironment : public ::testing::Environment {
 public:
  void SetUp() override {
    const char* api_name = std::getenv("ATRIUM_TEST_GL");
    const auto api = atrium::gfx::gl_api_from_name(api_name ? api_name : "auto");
    if (!api) {
      std::fprintf(stderr, "ATRIUM_TEST_GL=%s is not an API (auto, 4.5, 4.1, es3.0)\n", api_name);
      std::exit(2);
    }
    // Every test reads what its passes wrote, never what a new buffer happened to hold.
    atrium::gfx::set_allocation_poison(true);
    context_ = atrium::gfx::HeadlessContext::create(atrium::gfx::ContextOptions{.api = *api, .debug = true});
    std::printf("GL context: %s, %s, %s (%s)\n", context_->info().renderer.c_str(), context_->info().api.c_str(),
                context_->info().version.c_str(), context_->info().platform.c_str());
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
