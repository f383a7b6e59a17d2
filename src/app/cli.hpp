// The `atrium` command line: parsing (pure, testable; command_line.cpp) and the
// commands (cli.cpp).
// Exit codes: 0 success, 1 runtime failure, 2 bad usage or bad input.
#pragma once

#include <map>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

#include <glm/glm.hpp>

#include "gfx/context.hpp"
#include "app/bench.hpp"
#include "app/world.hpp"
#include "components/light.hpp"
#include "components/technique_options.hpp"

namespace atrium {

inline constexpr int kExitOk = 0;
inline constexpr int kExitRuntimeFailure = 1;
inline constexpr int kExitUsage = 2;
inline constexpr int kMaxImageSide = 16384;
// `atrium compare` fails when any mode's image is further than this from forward's.
inline constexpr double kMinimumPsnr = 40.0;

class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class Command { Window, Render, Info, Compare, Bench, Probe, Help, Version };

struct CliOptions {
  Command command = Command::Window;
  Command help_topic = Command::Window;  // help: the command whose options it lists (Window: the overview)
  std::string scene = "atrium";
  std::optional<std::string> mode;
  std::string shading = "pbr";
  std::string debug_view;  // empty: the lit image
  TechniqueOptions technique_options;  // --cluster-grid, --active-clusters
  std::optional<std::uint32_t> lights;
  std::optional<float> light_radius;  // --light-radius: one radius for every point and spot light
  int max_texture_size = 0;           // --max-texture-size; 0: the context's limit
  int view = 1;
  std::optional<assets::NamedView> camera;  // --camera X,Y,Z,YAW,PITCH: replaces the scene's views
  glm::ivec2 size{1280, 720};
  std::string out;                 // render: PNG path
  std::optional<std::uint64_t> frames;  // window: quit after this many frames
  bool json = false;                    // info, probe: print JSON
  bool memory = false;                  // info: every mode's render-target memory at --size
  bool frustum_culling = true;          // --no-culling
  bool occlusion_culling = true;        // --no-occlusion-culling
  CullingDevice culling_device = CullingDevice::Automatic;  // --culling
  bool poison_targets = false;          // --poison-targets
  // --lighting-stage: the window's and render's (absent: the scene file's, else
  // auto); compare's and bench's list (empty: their defaults).
  std::optional<LightingStage> lighting_stage;
  std::vector<LightingStage> lighting_stages;
  int shadows = 0;                      // --shadows K: lights with shadow maps
  std::map<std::string, double> system_options;  // rows of the system options table, by name
  bool gl_debug = false;                // KHR_debug output and a GL error count (on in debug builds)
  gfx::GlApi gl_api = gfx::GlApi::Auto; // --gl: which OpenGL the context asks for
  BenchOptions bench;                   // bench: the sweep
  std::string csv, md, plot;            // bench: output files
};

// Throws UsageError with a one-line message naming the bad argument.
[[nodiscard]] CliOptions parse_cli(std::span<const std::string_view> args);
// `atrium --help` (the overview), or one command's options for `atrium render --help`.
[[nodiscard]] std::string help_text(Command command = Command::Window);
[[nodiscard]] std::string version_text();

// Runs a parsed command; returns the process exit code.
int run_command(const CliOptions& options);
// parse + run, with every error turned into a message and an exit code.
int run_cli(int argc, char** argv);

int run_window(const CliOptions& options);

// The World every command builds from the parsed options.
[[nodiscard]] WorldOptions world_options(const CliOptions& options);

}  // namespace atrium
