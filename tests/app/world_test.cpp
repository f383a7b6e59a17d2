// What the window asks of the World between frames: changing the light count
// keeps the lights it had, and reloading shaders keeps a failing program's old
// version and reports the error.
#include <filesystem>
#include <fstream>

#include "app/world.hpp"
#include "assets/image.hpp"
#include "components/light.hpp"
#include "components/transform.hpp"
#include "gfx/shader_library.hpp"
#include "support/gl_test.hpp"

namespace atrium {
namespace {

using WorldControls = testing::GlTest;

std::vector<glm::vec3> light_positions(World& world) {
  std::vector<glm::vec3> positions;
  world.registry().view<Transform, LightColor>().each([&](const Transform& t, const LightColor&) { positions.push_back(t.position); });
  std::sort(positions.begin(), positions.end(), [](auto& a, auto& b) { return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z); });
  return positions;
}

TEST_F(WorldControls, DoublingAndHalvingTheLightsKeepsTheLightsThatStay) {
  World world({.scene = "atrium", .lights = 40u, .mode = "deferred", .size = {64, 36}});
  const auto forty = light_positions(world);
  world.set_light_count(80);
  world.frame(0.0);
  EXPECT_EQ(world.light_count(), 80u);
  EXPECT_EQ(world.renderer().stats().lights, 80u);
  const auto eighty = light_positions(world);
  for (const glm::vec3& p : forty) EXPECT_TRUE(std::binary_search(eighty.begin(), eighty.end(), p, [](auto& a, auto& b) {
    return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
  })) << "light at " << p.x << ", " << p.y << ", " << p.z << " moved or vanished";
  world.set_light_count(40);
  EXPECT_EQ(light_positions(world), forty) << "halving gives back the first forty";
  world.set_light_count(0);
  world.frame(0.0);
  EXPECT_EQ(world.renderer().stats().lights, 0u);
}

TEST_F(WorldControls, ShaderReloadKeepsTheOldProgramWhenTheNewOneFails) {
  const auto folder = std::filesystem::temp_directory_path() / ("atrium_reload_" + std::to_string(::getpid()));
  std::filesystem::create_directories(folder);
  auto write = [&](const char* body) {
    std::ofstream(folder / "probe.comp") << "#version 450 core\nlayout(local_size_x = 1) in;\n" << body;
  };
  ::setenv("ATRIUM_SHADER_DIR", folder.c_str(), 1);
  write("void main() {}\n");
  gfx::ShaderLibrary library;
  gfx::ShaderProgram& program = library.get({"probe.comp"});
  const GLuint first = program.id();

  write("void main() { undeclared = 1; }\n");
  const std::vector<std::string> errors = library.reload();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors[0].find("probe.comp:3"), std::string::npos) << errors[0];
  EXPECT_EQ(program.id(), first) << "the failing program keeps its old version";

  write("void main() { }\n");
  EXPECT_TRUE(library.reload().empty());
  EXPECT_NE(program.id(), first) << "the same object now holds the new program";
  EXPECT_TRUE(glIsProgram(program.id()));
  ::unsetenv("ATRIUM_SHADER_DIR");
  std::filesystem::remove_all(folder);
}

TEST_F(WorldControls, ReloadingTheEngineShadersKeepsThePicture) {
  World world({.scene = "atrium", .lights = 24u, .mode = "clustered-deferred", .size = {96, 54}});
  world.frame(0.0);
  const assets::Image before = world.renderer().read_output();
  EXPECT_TRUE(world.reload_shaders().empty());
  world.frame(0.0);
  EXPECT_GE(assets::psnr(before, world.renderer().read_output()), 60.0) << "uniforms were set again on the new programs";
}

}  // namespace
}  // namespace atrium
