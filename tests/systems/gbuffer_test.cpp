// The compact G-buffer's packing: octahedral normals survive their 2x16-bit
// encoding everywhere on the sphere (poles, the folded lower half, the seams),
// the two layouts cost the bytes per pixel the docs state, and each deferred
// mode draws nearly the same picture with either (docs/techniques.md quotes it).
#include <cmath>
#include <numbers>

#include <glm/glm.hpp>

#include "app/world.hpp"
#include "assets/image.hpp"
#include "support/compute_probe.hpp"
#include "support/gl_test.hpp"
#include "support/modes.hpp"
#include "systems/lighting/gbuffer.hpp"

namespace atrium {
namespace {

using CompactGBuffer = testing::GlTest;

std::vector<glm::vec4> sphere_directions() {
  std::vector<glm::vec4> directions;
  // A Fibonacci sphere covers every region evenly...
  constexpr int kCount = 20000;
  const float golden = std::numbers::pi_v<float> * (3.0f - std::sqrt(5.0f));
  for (int i = 0; i < kCount; ++i) {
    const float y = 1.0f - 2.0f * (static_cast<float>(i) + 0.5f) / kCount;
    const float r = std::sqrt(1.0f - y * y);
    directions.emplace_back(r * std::cos(golden * static_cast<float>(i)), y, r * std::sin(golden * static_cast<float>(i)), 0.0f);
  }
  // ...and the axes and the octahedron's edges are where encodings break.
  for (const glm::vec3 d : {glm::vec3(1, 0, 0), glm::vec3(-1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, -1, 0), glm::vec3(0, 0, 1),
                            glm::vec3(0, 0, -1), glm::vec3(1, 1, 0), glm::vec3(-1, 0, -1), glm::vec3(0, -1, -1e-7f),
                            glm::vec3(1, -1, -1), glm::vec3(-1e-7f, 1e-7f, -1)}) {
    directions.emplace_back(glm::normalize(d), 0.0f);
  }
  return directions;
}

TEST_F(CompactGBuffer, OctahedralNormalsRoundTripWithinATenThousandthOfARadian) {
  const std::vector<glm::vec4> directions = sphere_directions();
  const auto decoded = testing::evaluate_glsl<glm::vec4>(
      "#define COMPACT_GBUFFER\n#include \"common/frame.glsl\"\n#include \"common/surface.glsl\"\n#include \"common/gbuffer.glsl\"\n",
      "vec4", "vec4",
      "vec4(octahedral_decode(unpackUnorm2x16(packUnorm2x16(octahedral_encode(value.xyz) * 0.5 + 0.5)) * 2.0 - 1.0), 0.0)",
      directions);
  double worst = 0.0;
  for (std::size_t i = 0; i < directions.size(); ++i) {
    const glm::dvec3 in(directions[i]), out(decoded[i]);
    ASSERT_NEAR(glm::length(out), 1.0, 1e-5) << i;
    // atan2 of sine and cosine: acos loses small angles to rounding.
    const double angle = std::atan2(glm::length(glm::cross(in, out)), glm::dot(in, out));
    worst = std::max(worst, angle);
    EXPECT_LT(angle, 1e-4) << "normal (" << in.x << ", " << in.y << ", " << in.z << ")";
  }
  RecordProperty("worst_angle_radians", std::to_string(worst));
}

TEST(GBufferLayouts, CostTheBytesPerPixelTheDocsState) {
  EXPECT_EQ(lighting::GBuffer::bytes_per_pixel(lighting::GBufferLayout::Full), 44u);
  EXPECT_EQ(lighting::GBuffer::bytes_per_pixel(lighting::GBufferLayout::Compact), 24u);
  EXPECT_EQ(lighting::GBuffer::targets(lighting::GBufferLayout::Compact).size(), 2u);
  EXPECT_EQ(lighting::GBuffer::bytes_per_pixel(lighting::GBufferLayout::Thin), 16u) << "the light pre-pass's";
}

TEST_F(CompactGBuffer, DrawsWhatTheFullLayoutDrawsInEveryDeferredMode) {
  World full({"atrium", std::nullopt, "deferred", 1, {160, 90}, "pbr", "", testing::with_layout(lighting::GBufferLayout::Full)});
  World compact({"atrium", std::nullopt, "deferred", 1, {160, 90}, "pbr", "", testing::with_layout(lighting::GBufferLayout::Compact)});
  for (const std::string& mode : testing::non_forward_modes()) {
    if (mode == "clustered-forward") continue;  // no G-buffer
    double worst = 1e9;
    for (int view = 1; view <= 5; ++view) {
      for (World* world : {&full, &compact}) {
        world->set_mode(mode);
        world->set_view(view);
        world->frame(0.0);
      }
      const double psnr = assets::psnr(full.renderer().read_output(), compact.renderer().read_output());
      worst = std::min(worst, psnr);
      EXPECT_GE(psnr, 50.0) << mode << " view " << view;
    }
    RecordProperty(mode + "_worst_psnr_db", std::to_string(worst));
  }
}

}  // namespace
}  // namespace atrium
