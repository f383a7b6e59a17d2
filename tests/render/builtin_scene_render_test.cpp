// The built-in scene rendered headless at 320x180 from every stored view: each
// picture is lit (not blank), the views differ, and surfaces close to a light are
// brighter than surfaces far from every light.
#include <cmath>
#include <limits>

#include "app/world.hpp"
#include "assets/image.hpp"
#include "components/frame_resources.hpp"
#include "components/light.hpp"
#include "components/transform.hpp"
#include "support/gl_test.hpp"

namespace atrium {
namespace {

constexpr glm::ivec2 kSize{320, 180};

struct ViewFrame {
  assets::Image image;
  std::vector<float> depth;
  glm::mat4 inverse_view;
  glm::mat4 inverse_projection;
};

class BuiltinSceneRender : public testing::GlTest {
 protected:
  static void SetUpTestSuite() {
    World world({.scene = "atrium", .mode = "forward", .size = kSize});
    frames_ = new std::vector<ViewFrame>();
    for (int v = 1; v <= static_cast<int>(world.scene().views.size()); ++v) {
      world.set_view(v);
      world.frame(0.0);
      const auto& state = world.registry().resource<ViewState>();
      frames_->push_back({world.renderer().read_output(), world.renderer().read_view_depth(), glm::inverse(state.view),
                          glm::inverse(state.projection)});
      assets::write_png("builtin_view_" + std::to_string(v) + ".png", frames_->back().image);
    }
    world.registry().view<Transform, LightColor>().each([](const Transform& t, const LightColor&) {
      lights_.push_back(t.position);
    });
  }
  static void TearDownTestSuite() {
    delete frames_;
    frames_ = nullptr;
  }
  static std::vector<ViewFrame>* frames_;
  static std::vector<glm::vec3> lights_;
};
std::vector<ViewFrame>* BuiltinSceneRender::frames_ = nullptr;
std::vector<glm::vec3> BuiltinSceneRender::lights_;

TEST_F(BuiltinSceneRender, EveryViewIsLitAndNotBlank) {
  ASSERT_EQ(frames_->size(), 5u);
  for (std::size_t v = 0; v < frames_->size(); ++v) {
    const assets::Image& image = (*frames_)[v].image;
    double sum = 0, sum_sq = 0;
    int geometry = 0;
    for (int y = 0; y < kSize.y; ++y) {
      for (int x = 0; x < kSize.x; ++x) {
        const double l = assets::luma(image, x, y);
        sum += l;
        sum_sq += l * l;
        geometry += (*frames_)[v].depth[static_cast<std::size_t>(y * kSize.x + x)] < std::numeric_limits<float>::infinity();
      }
    }
    const double n = kSize.x * kSize.y, mean = sum / n, stddev = std::sqrt(sum_sq / n - mean * mean);
    EXPECT_GT(mean, 0.12) << "view " << v + 1 << " is too dark";
    EXPECT_LT(mean, 0.85) << "view " << v + 1 << " is washed out";
    EXPECT_GT(stddev, 0.05) << "view " << v + 1 << " has no contrast";
    EXPECT_GT(geometry, n * 0.6) << "view " << v + 1 << " shows too little of the scene";
  }
}

TEST_F(BuiltinSceneRender, ViewsDiffer) {
  for (std::size_t a = 0; a < frames_->size(); ++a) {
    for (std::size_t b = a + 1; b < frames_->size(); ++b) {
      EXPECT_LT(assets::psnr((*frames_)[a].image, (*frames_)[b].image), 20.0) << "views " << a + 1 << " and " << b + 1;
    }
  }
}

TEST_F(BuiltinSceneRender, SurfacesNearLightsAreBrighterThanSurfacesFarFromThem) {
  for (std::size_t v = 0; v < frames_->size(); ++v) {
    const ViewFrame& frame = (*frames_)[v];
    double near_sum = 0, far_sum = 0;
    int near_count = 0, far_count = 0;
    for (int y = 0; y < kSize.y; ++y) {
      for (int x = 0; x < kSize.x; ++x) {
        const float depth = frame.depth[static_cast<std::size_t>(y * kSize.x + x)];
        if (!std::isfinite(depth)) continue;
        // The pixel's ray at view depth 1, scaled to the surface's depth.
        const glm::vec4 ndc((x + 0.5f) / kSize.x * 2 - 1, 1 - (y + 0.5f) / kSize.y * 2, 0.5f, 1);
        const glm::vec4 on_ray = frame.inverse_projection * ndc;
        const glm::vec3 ray = glm::vec3(on_ray) / on_ray.w / (-on_ray.z / on_ray.w);
        const glm::vec3 p = glm::vec3(frame.inverse_view * glm::vec4(ray * depth, 1.0f));
        float nearest = 1e9f;
        for (const glm::vec3& light : lights_) nearest = std::min(nearest, glm::distance(light, p));
        const double l = assets::luma(frame.image, x, y);
        if (nearest < 1.0f) {
          near_sum += l;
          ++near_count;
        } else if (nearest > 3.0f) {
          far_sum += l;
          ++far_count;
        }
      }
    }
    ASSERT_GT(near_count, 50) << "view " << v + 1 << " shows no surface near a light";
    ASSERT_GT(far_count, 50) << "view " << v + 1;
    const double near_mean = near_sum / near_count, far_mean = far_sum / far_count;
    EXPECT_GT(near_mean, far_mean * 1.3) << "view " << v + 1 << ": near " << near_mean << " far " << far_mean;
  }
}

}  // namespace
}  // namespace atrium
