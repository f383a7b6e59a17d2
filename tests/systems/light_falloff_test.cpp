// The GLSL falloff (shaders/common/attenuation.glsl) and the C++ one
// (light_falloff.cpp) are one definition in two languages: a compute shader
// evaluates the GLSL at many (distance, radius) pairs and the results must
// match the C++ function.
#include <cmath>
#include <filesystem>
#include <fstream>

#include "gfx/shader_program.hpp"
#include "support/gl_test.hpp"
#include "systems/lighting/light_falloff.hpp"

namespace atrium::lighting {
namespace {

using LightFalloff = testing::GlTest;

std::vector<float> evaluate_glsl(const std::vector<glm::vec2>& samples) {
  const auto folder = std::filesystem::temp_directory_path() / ("atrium_falloff_" + std::to_string(::getpid()));
  std::filesystem::create_directories(folder);
  std::ofstream(folder / "falloff_probe.comp")
      << "#version 450 core\n"
         "layout(local_size_x = 64) in;\n"
         "#include \"common/attenuation.glsl\"\n"
         "layout(std430, binding = 1) readonly buffer Samples { vec2 samples[]; };\n"
         "layout(std430, binding = 2) writeonly buffer Results { float results[]; };\n"
         "uniform uint u_count;\n"
         "void main() {\n"
         "  uint i = gl_GlobalInvocationID.x;\n"
         "  if (i < u_count) results[i] = light_attenuation(samples[i].x, samples[i].y);\n"
         "}\n";
  gfx::ShaderSearchPath path{folder};
  for (const auto& p : gfx::default_shader_path()) path.push_back(p);
  gfx::ShaderProgram program = gfx::ShaderProgram::load({"falloff_probe.comp"}, {}, path);
  std::filesystem::remove_all(folder);

  gfx::Buffer input = gfx::create_buffer();
  gfx::Buffer output = gfx::create_buffer();
  glNamedBufferStorage(input.id(), static_cast<GLsizeiptr>(samples.size() * sizeof(glm::vec2)), samples.data(), 0);
  glNamedBufferStorage(output.id(), static_cast<GLsizeiptr>(samples.size() * sizeof(float)), nullptr, 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, input.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, output.id());
  program.set("u_count", static_cast<unsigned>(samples.size()));
  program.use();
  glDispatchCompute(static_cast<GLuint>((samples.size() + 63) / 64), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<float> results(samples.size());
  glGetNamedBufferSubData(output.id(), 0, static_cast<GLsizeiptr>(results.size() * sizeof(float)), results.data());
  return results;
}

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
  const std::vector<float> gpu = evaluate_glsl(samples);
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

}  // namespace
}  // namespace atrium::lighting
