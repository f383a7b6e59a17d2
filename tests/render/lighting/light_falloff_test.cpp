// The GLSL falloff (shaders/common/attenuation.glsl) and the C++ one
// (light_falloff.cpp) are one definition in two languages: a compute shader
// evaluates the GLSL at many (distance, radius) pairs and the results must
// match the C++ function.
#include <cmath>

#include "support/compute_probe.hpp"
#include "support/gl_test.hpp"
#include "render/lighting/light_falloff.hpp"

namespace atrium::lighting {
namespace {

using LightFalloff = testing::GlTest;

TEST_F(LightFalloff, GlslAndCppAgreeEverywhere) {
  std::vector<glm::vec2> samples;
  for (float radius : {0.5f, 1.0f, 3.7f, 8.0f, 37.5f}) {
    for (int i = 0; i <= 240; ++i) samples.emplace_back(radius * 1.2f * static_cast<float>(i) / 240.0f, radius);
    samples.emplace_back(radius, radius);           // exactly at the radius
    samples.emplace_back(0.0f, radius);             // at the light
    samples.emplace_back(kMinLightDistance * 0.5f, radius);
  }
  samples.emplace_back(1.0f, 0.0f);   // no radius: no light
  samples.emplace_back(1.0f, -2.0f);  // negative radius: no light
  const std::vector<float> gpu = testing::evaluate_glsl<float>(
      "#include \"common/attenuation.glsl\"\n", "vec2", "float", "light_attenuation(value.x, value.y)", samples);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const float cpu = light_attenuation(samples[i].x, samples[i].y);
    EXPECT_NEAR(gpu[i], cpu, 1e-5f * std::max(1.0f, std::abs(cpu)))
        << "distance " << samples[i].x << " radius " << samples[i].y;
  }
}

TEST(LightFalloffCpp, ReachesExactlyZeroAtTheRadiusAndStaysThere) {
  EXPECT_EQ(light_attenuation(5.0f, 5.0f), 0.0f);
  EXPECT_EQ(light_attenuation(7.0f, 5.0f), 0.0f);
  EXPECT_GT(light_attenuation(4.99f, 5.0f), 0.0f);
}

TEST(LightFalloffCpp, IsInverseSquareWellInsideTheRadius) {
  // At a tenth of the radius the window is (1 - 1e-4)^2: inverse-square to 3e-4.
  EXPECT_NEAR(light_attenuation(1.0f, 10.0f), 1.0f, 3e-4f);
  EXPECT_NEAR(light_attenuation(0.5f, 10.0f) / light_attenuation(1.0f, 10.0f), 4.0f, 1e-3f);
}

TEST(LightFalloffCpp, DecreasesMonotonically) {
  float previous = light_attenuation(0.0f, 4.0f);
  for (int i = 1; i <= 400; ++i) {
    const float value = light_attenuation(4.0f * static_cast<float>(i) / 400.0f, 4.0f);
    EXPECT_LE(value, previous);
    previous = value;
  }
}

TEST(LightFalloffCpp, DerivedRadiusIsWhereTheBrightestChannelFallsToTheThreshold) {
  const glm::vec3 color(0.2f, 1.0f, 0.5f);
  const float intensity = 3.0f;
  const float r = light_radius_from_intensity(color, intensity);
  EXPECT_NEAR(intensity * 1.0f / (r * r), kRadiusThreshold, 1e-7f);
  EXPECT_NEAR(r, std::sqrt(3.0f * 256.0f / 5.0f), 1e-4f);
  EXPECT_EQ(light_radius_from_intensity(glm::vec3(0.0f), 10.0f), 0.0f);
  EXPECT_EQ(light_radius_from_intensity(glm::vec3(1.0f), 0.0f), 0.0f);
}

TEST(LightFalloffCpp, IntensityForRadiusIsTheInverseOfTheDerivedRadius) {
  for (const glm::vec3 color : {glm::vec3(0.2f, 1.0f, 0.5f), glm::vec3(3.0f, 0.1f, 0.1f), glm::vec3(0.01f)}) {
    for (const float radius : {0.1f, 1.0f, 4.0f, 40.0f}) {
      EXPECT_NEAR(light_radius_from_intensity(color, intensity_for_radius(color, radius)), radius, radius * 1e-5f);
    }
  }
  EXPECT_TRUE(std::isfinite(intensity_for_radius(glm::vec3(0.0f), 2.0f)));
}

}  // namespace
}  // namespace atrium::lighting
