#include <gtest/gtest.h>

#include <map>
#include <sstream>

#include "app/cli.hpp"
#include "render/techniques/technique.hpp"

namespace atrium {
namespace {

CliOptions parse(std::initializer_list<std::string_view> args) {
  const std::vector<std::string_view> list(args);
  return parse_cli(list);
}

std::string usage_error(std::initializer_list<std::string_view> args) {
  try {
    (void)parse(args);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(Cli, DefaultsToTheWindowOnTheBuiltInScene) {
  const CliOptions o = parse({});
  EXPECT_EQ(o.command, Command::Window);
  EXPECT_EQ(o.scene, "atrium");
  EXPECT_EQ(o.view, 1);
  EXPECT_FALSE(o.lights.has_value());
  EXPECT_FALSE(o.mode.has_value());
}

TEST(Cli, ParsesRenderWithEveryOption) {
  const CliOptions o = parse({"render", "atrium", "--out", "x.png", "--mode", "forward", "--lights", "512", "--view", "3",
                              "--size", "640x360"});
  EXPECT_EQ(o.command, Command::Render);
  EXPECT_EQ(o.out, "x.png");
  EXPECT_EQ(*o.mode, "forward");
  EXPECT_EQ(*o.lights, 512u);
  EXPECT_EQ(o.view, 3);
  EXPECT_EQ(o.size, glm::ivec2(640, 360));
}

TEST(Cli, HelpWinsAndListsEveryMode) {
  EXPECT_EQ(parse({"--lights", "3", "--help"}).command, Command::Help);
  for (const auto& info : techniques::technique_table()) {
    EXPECT_NE(help_text().find("  " + std::string(info.name) + " "), std::string::npos) << info.name;
  }
}

TEST(Cli, BadArgumentsNameTheProblem) {
  EXPECT_EQ(usage_error({"--frobnicate"}), "unknown option '--frobnicate' (see atrium --help)");
  EXPECT_EQ(usage_error({"render"}), "render needs --out FILE.png");
  EXPECT_EQ(usage_error({"--out", "x.png"}), "--out is for `atrium render`");
  EXPECT_EQ(usage_error({"--lights"}), "--lights needs a value");
  EXPECT_EQ(usage_error({"--lights", "-1"}), "--lights expects a whole number from 0 to 1048576, got '-1'");
  EXPECT_EQ(usage_error({"--lights", "12abc"}), "--lights expects a whole number from 0 to 1048576, got '12abc'");
  EXPECT_EQ(usage_error({"--view", "0"}), "--view expects a whole number from 1 to 1000, got '0'");
  EXPECT_EQ(usage_error({"--size", "640"}), "--size expects WIDTHxHEIGHT (e.g. 640x360), got '640'");
  EXPECT_EQ(usage_error({"--size", "0x10"}), "--size expects WIDTHxHEIGHT with each side from 1 to 16384, got '0x10'");
  EXPECT_EQ(usage_error({"--mode", "deferred-ish"}).rfind("unknown mode 'deferred-ish' (modes: forward", 0), 0u);
  EXPECT_EQ(usage_error({"--gl", "es2.0"}), "unknown --gl 'es2.0' (expected auto, 4.5, 4.1 or es3.0)");
  EXPECT_EQ(usage_error({"a", "b"}), "unexpected argument 'b' (one scene at most)");
}

TEST(Cli, TakesTheGnuFormAndTheLastOfARepeatedOption) {
  const CliOptions o = parse({"render", "--out=x.png", "--mode=deferred", "--lights", "3", "--lights=7", "--size=64x36"});
  EXPECT_EQ(o.out, "x.png");
  EXPECT_EQ(*o.mode, "deferred");
  EXPECT_EQ(*o.lights, 7u);
  EXPECT_EQ(o.size, glm::ivec2(64, 36));
  EXPECT_EQ(usage_error({"--lights=many"}), "--lights expects a whole number from 0 to 1048576, got 'many'");
}

// --cluster-grid: tiles in pixels (NpxxZ, Npx) or clusters per axis (XxYxZ);
// a pixel grid follows the frame's size, with at least 16x9 tiles and at most 2^18 clusters.
TEST(Cli, ClusterGridsInPixelsOrPerAxis) {
  EXPECT_EQ(parse({"render", "--out", "x.png"}).technique_options.cluster_grid, ClusterGridSize::pixels(24, 32));
  EXPECT_EQ(parse({"render", "--out", "x.png", "--cluster-grid", "40pxx12"}).technique_options.cluster_grid, ClusterGridSize::pixels(40, 12));
  EXPECT_EQ(parse({"render", "--out", "x.png", "--cluster-grid", "16px"}).technique_options.cluster_grid, ClusterGridSize::pixels(16, 32));
  EXPECT_EQ(parse({"render", "--out", "x.png", "--cluster-grid", "16x9x24"}).technique_options.cluster_grid,
            ClusterGridSize::fixed({16, 9, 24}));
  EXPECT_EQ(usage_error({"render", "--out", "x.png", "--cluster-grid", "24pxy"}),
            "--cluster-grid expects NpxxZ, Npx or XxYxZ (e.g. 24pxx32, 16x9x32), got '24pxy'");
  EXPECT_EQ(usage_error({"render", "--out", "x.png", "--cluster-grid", "4px"}), "--cluster-grid expects a whole number from 8 to 512, got '4'");

  const ClusterGridSize grid;
  EXPECT_EQ(grid.at({1920, 1080}), glm::uvec3(80, 45, 32));
  EXPECT_EQ(grid.at({320, 180}), glm::uvec3(16, 9, 32)) << "never fewer tiles than the 16x9 of the fixed grid before";
  EXPECT_EQ(grid.at({640, 360}), glm::uvec3(27, 15, 32));
  EXPECT_EQ(grid.at({3840, 2160}), glm::uvec3(120, 68, 32)) << "4K: 32-pixel tiles, 261,120 clusters";
  const glm::uvec3 huge = grid.at({8192, 8192});
  EXPECT_LE(std::uint64_t{huge.x} * huge.y * huge.z, ClusterGridSize::kMaxPixelClusters);
  EXPECT_GT(std::uint64_t{huge.x} * huge.y * huge.z, ClusterGridSize::kMaxPixelClusters * 9 / 10);
  EXPECT_EQ(ClusterGridSize::fixed({16, 9, 24}).at({8192, 8192}), glm::uvec3(16, 9, 24));
}

TEST(Cli, VersionAndPerCommandHelp) {
  EXPECT_EQ(parse({"--version"}).command, Command::Version);
  EXPECT_EQ(version_text().rfind("atrium ", 0), 0u);  // the number itself: the version CLI test
  const CliOptions help = parse({"render", "--out", "x.png", "--help"});
  EXPECT_EQ(help.command, Command::Help);
  EXPECT_EQ(help.help_topic, Command::Render);
  EXPECT_EQ(parse({"--help"}).help_topic, Command::Window);
  const std::string render = help_text(Command::Render);
  EXPECT_EQ(render.rfind("Usage: atrium render", 0), 0u);
  EXPECT_NE(render.find("\n  --out FILE.png "), std::string::npos);
  EXPECT_EQ(render.find("--json"), std::string::npos);
  EXPECT_EQ(render.find("--modes"), std::string::npos);
  const std::string info = help_text(Command::Info);
  EXPECT_NE(info.find("\n  --json "), std::string::npos);
  EXPECT_EQ(info.find("--mode"), std::string::npos);
  EXPECT_NE(help_text(Command::Bench).find("\n  --lights LIST "), std::string::npos);
}

TEST(Cli, ProbeMeasuresAt1080pAndDrawsNoScene) {
  const CliOptions probe = parse({"probe", "--json"});
  EXPECT_EQ(probe.command, Command::Probe);
  EXPECT_EQ(probe.size, glm::ivec2(1920, 1080));
  EXPECT_TRUE(probe.json);
  EXPECT_EQ(parse({"probe", "--size", "320x180"}).size, glm::ivec2(320, 180));
  EXPECT_EQ(usage_error({"probe", "scenes/sponza.json"}), "probe draws no scene; 'scenes/sponza.json' does not apply");
  EXPECT_EQ(usage_error({"probe", "--mode", "deferred"}), "--mode is for the window and `atrium render`");
  EXPECT_NE(help_text(Command::Probe).find("GL_NV_shader_thread_group"), std::string::npos);
}

TEST(Cli, SuggestsTheNearestOptionAndNamesWhereAnOptionBelongs) {
  EXPECT_EQ(usage_error({"--ligths", "5"}), "unknown option '--ligths' (did you mean --lights? see atrium --help)");
  EXPECT_EQ(usage_error({"render", "--out", "x.png", "--shadng=pbr"}),
            "unknown option '--shadng' (did you mean --shading? see atrium render --help)");
  EXPECT_EQ(usage_error({"info", "--debug-view", "heatmap"}), "--debug-view is for the window and `atrium render`");
  EXPECT_EQ(usage_error({"render", "--out", "x.png", "--frames", "3"}), "--frames is for the window and `atrium bench`");
  EXPECT_EQ(usage_error({"--debug-view", "depth", "info"}), "--debug-view is for the window and `atrium render`");
  EXPECT_EQ(usage_error({"compare", "--mode", "deferred"}), "compare renders every mode; --mode does not apply");
  EXPECT_EQ(usage_error({"render", "--out", "x.png", "--view"}), "--view needs a value");
}

// Every option a command's help lists is one that command accepts: the help,
// the parser and the code that reads the values come from one table.
TEST(Cli, EveryOptionInACommandsHelpIsAccepted) {
  const std::map<std::string, std::string> sample{
      {"--mode", "deferred"},       {"--shading", "phong"},          {"--cluster-grid", "8x4x8"},
      {"--cluster-bounds", "grid"}, {"--z-slicing", "uniform"},      {"--gbuffer", "compact"}, {"--culling", "gpu"}, {"--gl", "es3.0"},
      {"--debug-view", "depth"},    {"--lights", "5"},               {"--light-radius", "2"},
      {"--max-texture-size", "64"}, {"--view", "2"},                 {"--camera", "0,1,2,0,0"},
      {"--size", "32x18"},          {"--out", "x.png"},              {"--frames", "2"},
      {"--warmup", "1"},            {"--frame-limit", "250"},        {"--modes", "forward,deferred"}, {"--views", "1,2"},
      {"--csv", "x.csv"},           {"--md", "x.md"},                {"--plot", "x.png"},
      {"--msaa", "2"},              {"--shadows", "4"},              {"--fireflies", "3"},
      {"--lighting-stage", "compute"}, {"--light-assignment", "gather"}, {"--material-binding", "bound"},
      {"--bloom", "0.04"},          {"--bloom-radius", "0.3"}};
  for (const Command command : {Command::Window, Command::Render, Command::Info, Command::Compare, Command::Bench, Command::Probe}) {
    std::istringstream help(help_text(command));
    int options = 0;
    for (std::string line; std::getline(help, line);) {
      if (!line.starts_with("  --") || line.starts_with("  --help")) continue;
      const std::string name = line.substr(2, line.find(' ', 2) - 2);
      const bool flag = line[2 + name.size() + 1] == ' ';
      // The overview lists every option, tagging those only some commands take.
      const std::size_t tag = line.find(" [");
      if (command == Command::Window && tag != std::string::npos && line.find("window", tag) == std::string::npos) continue;
      std::vector<std::string> args;
      if (command == Command::Render) args = {"render", "--out", "x.png"};
      if (command == Command::Info) args = {"info"};
      if (command == Command::Compare) args = {"compare"};
      if (command == Command::Bench) args = {"bench"};
      if (command == Command::Probe) args = {"probe"};
      if (flag) {
        args.push_back(name);
      } else {
        ASSERT_TRUE(sample.contains(name)) << "give " << name << " a sample value in this test";
        args.push_back(name + "=" + sample.at(name));
      }
      const std::vector<std::string_view> views(args.begin(), args.end());
      EXPECT_NO_THROW((void)parse_cli(views)) << line;
      ++options;
    }
    EXPECT_GE(options, command == Command::Probe ? 2 : 3);
  }
}

TEST(Cli, AcceptsTheExtremeLightCounts) {
  EXPECT_EQ(*parse({"--lights", "0"}).lights, 0u);
  EXPECT_EQ(*parse({"--lights", "1000000"}).lights, 1'000'000u);
  EXPECT_EQ(*parse({"--lights", "1048576"}).lights, 1u << 20) << "2^20, the million lights of the papers";
  EXPECT_EQ(usage_error({"--lights", "1048577"}), "--lights expects a whole number from 0 to 1048576, got '1048577'");
}

}  // namespace
}  // namespace atrium
