// The fireflies system (src/systems/fireflies), the example of a system that
// draws: N Firefly entities that are point lights, made and destroyed as N
// changes; their sprites and light visibly change the frame, and every mode
// draws that frame as forward does; the option comes from the command line
// and scene files; and the system lives in its own files, joined to the
// engine by one registration line and one option row.
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "app/cli.hpp"
#include "app/world.hpp"
#include "assets/image.hpp"
#include "assets/scene_file.hpp"
#include "components/light.hpp"
#include "components/system_options.hpp"
#include "support/gl_test.hpp"
#include "support/modes.hpp"
#include "support/source_mentions.hpp"
#include "systems/fireflies/firefly.hpp"

namespace atrium {
namespace {
namespace fs = std::filesystem;

using testing::kSize;

using FirefliesTest = testing::GlTest;

WorldOptions options_with(int fireflies, const std::string& mode = "forward") {
  WorldOptions options;
  options.size = kSize;
  options.mode = mode;
  options.lights = 16;
  options.system_options["fireflies"] = fireflies;
  return options;
}

std::size_t count_fireflies(ecs::Registry& registry) {
  std::size_t n = 0;
  registry.view<Firefly, Transform, LightColor, LightRadius>().each([&](ecs::Entity, const Firefly&, const Transform&, const LightColor&,
                                                                        const LightRadius&) { ++n; });
  return n;
}

TEST_F(FirefliesTest, KeepsAsManyLightsAsAskedAndMakesAndDestroysThemAsThatChanges) {
  World world(options_with(48));
  world.frame(0.0);
  EXPECT_EQ(count_fireflies(world.registry()), 48u);
  EXPECT_EQ(world.renderer().stats().lights, 16u + 48u) << "each firefly is a light of the frame";
  for (const int n : {8, 200, 0}) {
    world.registry().resource<SystemOptions>().set("fireflies", n);
    world.frame(0.0);
    EXPECT_EQ(count_fireflies(world.registry()), static_cast<std::size_t>(n));
    EXPECT_EQ(world.renderer().stats().lights, 16u + static_cast<std::uint32_t>(n));
  }
}

TEST_F(FirefliesTest, TheyChangeTheFrameVisiblyAndEveryModeDrawsThemAsForwardDoes) {
  auto render = [](int fireflies, const std::string& mode) {
    World world(options_with(fireflies, mode));
    world.frame(0.0);
    return world.renderer().read_output();
  };
  const assets::Image without = render(0, "forward");
  const assets::Image with = render(96, "forward");
  assets::write_png("fireflies_forward.png", with);
  EXPECT_LT(assets::psnr(without, with), 35.0) << "96 fireflies show";
  for (const std::string& mode : testing::non_forward_modes()) {
    const assets::Image image = render(96, mode);
    assets::write_png("fireflies_" + mode + ".png", image);
    EXPECT_GE(assets::psnr(with, image), kMinimumPsnr) << mode;
  }
}

TEST_F(FirefliesTest, TheOptionComesFromTheCommandLineAndSceneFiles) {
  const std::string_view args[] = {"render", "--fireflies", "12", "--out", "x.png"};
  EXPECT_EQ(parse_cli(args).system_options.at("fireflies"), 12.0);
  const std::string_view too_many[] = {"render", "--fireflies", "5000", "--out", "x.png"};
  EXPECT_THROW((void)parse_cli(too_many), UsageError);
  const fs::path file = fs::temp_directory_path() / ("atrium_fireflies_" + std::to_string(::getpid()) + ".json");
  std::ofstream(file) << R"({"models": [{"builtin": "atrium"}], "systems": {"fireflies": 7}})";
  assets::AssetManager assets;
  assets::LoadReport report;
  const assets::SceneDescription scene = assets::load_scene_file(file, assets, report);
  fs::remove(file);
  EXPECT_EQ(scene.system_options.at("fireflies"), 7.0);
}

// Every file under src/ and shaders/ that mentions fireflies: the system's own
// folders, and in the rest of the engine only its registration (and include)
// in app/world.cpp and its option row in app/command_line.cpp.
TEST(FirefliesCode, LivesInItsOwnFilesPlusOneRegistrationAndOneOptionRow) {
  EXPECT_EQ(testing::mentions_outside("firefl", {"src/systems/fireflies/", "shaders/fireflies/"}),
            (std::map<std::string, int>{{"src/app/command_line.cpp", 2}, {"src/app/world.cpp", 2}}));
}

}  // namespace
}  // namespace atrium
