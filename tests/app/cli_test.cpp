#include <gtest/gtest.h>

#include "app/cli.hpp"
#include "systems/lighting/technique.hpp"

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
  for (const auto& info : lighting::technique_table()) {
    EXPECT_NE(help_text().find("  " + std::string(info.name) + " "), std::string::npos) << info.name;
  }
}

TEST(Cli, BadArgumentsNameTheProblem) {
  EXPECT_EQ(usage_error({"--frobnicate"}), "unknown option '--frobnicate' (see atrium --help)");
  EXPECT_EQ(usage_error({"render"}), "render needs --out FILE.png");
  EXPECT_EQ(usage_error({"--out", "x.png"}), "--out is for `atrium render`");
  EXPECT_EQ(usage_error({"--lights"}), "--lights needs a value");
  EXPECT_EQ(usage_error({"--lights", "-1"}), "--lights expects a whole number from 0 to 1000000, got '-1'");
  EXPECT_EQ(usage_error({"--lights", "12abc"}), "--lights expects a whole number from 0 to 1000000, got '12abc'");
  EXPECT_EQ(usage_error({"--view", "0"}), "--view expects a whole number from 1 to 1000, got '0'");
  EXPECT_EQ(usage_error({"--size", "640"}), "--size expects WIDTHxHEIGHT (e.g. 640x360), got '640'");
  EXPECT_EQ(usage_error({"--size", "0x10"}), "--size expects WIDTHxHEIGHT with each side from 1 to 16384, got '0x10'");
  EXPECT_EQ(usage_error({"--mode", "deferred-ish"}).rfind("unknown mode 'deferred-ish' (modes: forward", 0), 0u);
  EXPECT_EQ(usage_error({"a", "b"}), "unexpected argument 'b' (one scene at most)");
}

TEST(Cli, AcceptsTheExtremeLightCounts) {
  EXPECT_EQ(*parse({"--lights", "0"}).lights, 0u);
  EXPECT_EQ(*parse({"--lights", "1000000"}).lights, 1'000'000u);
}

}  // namespace
}  // namespace atrium
