// The `atrium` command line, parsed by CLI11. One table names every option,
// the commands that take it, what it means and, in each row, the code that
// reads its value; the parser, the overview (`atrium --help`) and each
// command's help (`atrium render --help`) are all built from it, so an option
// is added in one place.
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <sstream>
#include <type_traits>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/cli.hpp"
#include "app/demo_keys.hpp"
#include "assets/model_import.hpp"
#include "render/debug/debug_views.hpp"
#include "render/lighting/shading_model.hpp"
#include "render/techniques/technique.hpp"
#include "render/lighting/gbuffer.hpp"
#include "render/lighting/lighting_pass.hpp"
#include "gfx/limits.hpp"
#include "render/shadows/shadow_selection.hpp"

namespace atrium {
namespace {

constexpr unsigned on(Command command) { return 1u << static_cast<unsigned>(command); }
constexpr unsigned kWindow = on(Command::Window), kRender = on(Command::Render), kInfo = on(Command::Info),
                   kCompare = on(Command::Compare), kBench = on(Command::Bench), kProbe = on(Command::Probe);
constexpr unsigned kDrawing = kWindow | kRender | kCompare | kBench;  // the commands that draw frames

struct CommandSpec {
  Command command;
  std::string_view name;  // empty: the window, which is `atrium` with no command
  std::string_view usage;
  std::string_view summary;
};

// The compare line of the commands below states kMinimumPsnr.
static_assert(kMinimumPsnr == 40.0, "atrium compare --help states 40 dB");

constexpr std::array kCommands{
    CommandSpec{Command::Window, "", "atrium [SCENE] [options]", "open the demo window"},
    CommandSpec{Command::Render, "render", "atrium render [SCENE] --out FILE.png [options]",
                "render one frame headless to a PNG"},
    CommandSpec{Command::Info, "info", "atrium info [SCENE] [options]", "what the scene holds and what loading cost"},
    CommandSpec{Command::Compare, "compare", "atrium compare [SCENE] [options]",
                "every mode at every view against forward (PSNR, largest difference); exit 1 under 40 dB"},
    CommandSpec{Command::Bench, "bench", "atrium bench [SCENE] [options]",
                "frame and pass times over modes, light counts and views (default: all modes, 10,50,110,1024 "
                "lights, all views, 320x180, 30 frames, 5 warm-up)"},
    CommandSpec{Command::Probe, "probe", "atrium probe [options]",
                "the GPU's SMs that compute and fragment shaders run on (NVIDIA's GL_NV_shader_thread_group), the same "
                "arithmetic timed in each stage, and small triangles rasterised by the raster pipeline and by compute "
                "(default 1920x1080)"},
};

const CommandSpec& command_spec(Command command) {
  return *std::find_if(kCommands.begin(), kCommands.end(), [&](const CommandSpec& c) { return c.command == command; });
}

// Each row reads its own value into CliOptions.
using ApplyOption = std::function<void(std::string_view value, CliOptions& options)>;

struct OptionSpec {
  std::string name;   // "--lights"
  std::string value;  // "N"; empty for a flag
  unsigned commands;  // which commands take it
  std::string help;
  ApplyOption apply;
};

// Options of optional systems (components/system_options.hpp): each row is
// parsed by its own range into CliOptions::system_options under its name
// without the dashes, which is the name the system reads.
struct SystemOptionSpec {
  std::string_view name;  // with its dashes
  std::string_view value;
  std::string_view help;
  double min, max;
  bool whole;  // a count: refused unless a whole number
};

constexpr std::array kSystemOptions{
    SystemOptionSpec{"--fireflies", "N", "N small point lights wandering through the scene, each drawn as a glowing sprite (0..4096; "
                     "a scene file's \"systems\": {\"fireflies\": N})", 0, 4096, true},
    SystemOptionSpec{"--bloom", "S", "bloom: bright light glows over its surroundings, the image moved towards the glow by S (0..1, "
                     "0 off, the default; 0.04 is subtle; a scene file's \"systems\": {\"bloom\": S})", 0, 1, false},
    SystemOptionSpec{"--bloom-radius", "R", "how far the bloom's glow reaches, as a fraction of the image height (0.02..1, default 0.2; "
                     "a scene file's \"systems\": {\"bloom-radius\": R})", 0.02, 1, false},
};

// "5 targets, 48 B/px": a layout's targets and bytes per pixel with depth.
std::string gbuffer_size(GBufferLayout layout) {
  return std::to_string(lighting::GBuffer::targets(layout).size()) + " targets, " + std::to_string(lighting::GBuffer::bytes_per_pixel(layout)) +
         " B/px";
}

// The enumerator whose name is `text`; `what` and `plural` word the refusal:
// "unknown G-buffer layout 'x' (layouts: full, compact)".
template <typename Enum, std::size_t N>
Enum parse_choice(std::string_view text, const std::array<std::string_view, N>& names, const char* what, const char* plural) {
  const auto found = std::find(names.begin(), names.end(), text);
  if (found == names.end()) {
    std::string list;
    for (const std::string_view name : names) list += (list.empty() ? "" : ", ") + std::string(name);
    throw UsageError("unknown " + std::string(what) + " '" + std::string(text) + "' (" + plural + ": " + list + ")");
  }
  return static_cast<Enum>(found - names.begin());
}

template <typename T>
T parse_number(std::string_view flag, std::string_view text, T min, T max) {
  T value{};
  bool whole_text = false;
  if constexpr (std::is_integral_v<T>) {
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    whole_text = error == std::errc() && end == text.data() + text.size();
  } else {
    // strtod: the WebAssembly build's library has no from_chars for floating point.
    const std::string copy(text);
    char* end = nullptr;
    value = static_cast<T>(std::strtod(copy.c_str(), &end));
    whole_text = !copy.empty() && end == copy.c_str() + copy.size();
  }
  // Written so that NaN, which compares false with everything, is refused.
  if (!whole_text || !(value >= min && value <= max)) {
    const auto shown = [](T bound) {
      std::ostringstream out;
      out << bound;
      return out.str();
    };
    throw UsageError(std::string(flag) + " expects " + (std::is_integral_v<T> ? "a whole number" : "a number") + " from " + shown(min) +
                     " to " + shown(max) + ", got '" + std::string(text) + "'");
  }
  return value;
}

glm::ivec2 parse_size(std::string_view text) {
  const auto x = text.find('x');
  if (x == std::string_view::npos) throw UsageError("--size expects WIDTHxHEIGHT (e.g. 640x360), got '" + std::string(text) + "'");
  try {
    return {parse_number<int>("--size", text.substr(0, x), 1, kMaxImageSide),
            parse_number<int>("--size", text.substr(x + 1), 1, kMaxImageSide)};
  } catch (const UsageError&) {
    throw UsageError("--size expects WIDTHxHEIGHT with each side from 1 to " + std::to_string(kMaxImageSide) +
                     ", got '" + std::string(text) + "'");
  }
}

LightingStage parse_lighting_stage(std::string_view text) {
  return parse_choice<LightingStage>(text, kLightingStageNames, "lighting stage", "stages");
}

std::vector<std::string> split_list(std::string_view text) {
  std::vector<std::string> items;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = text.find(',', start);
    const std::string_view item = text.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start);
    if (!item.empty()) items.emplace_back(item);
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return items;
}

// The items of a comma-separated list option, each read by `parse`, in order
// and without repeats (measuring one twice would only repeat its rows).
template <typename T, typename Parse>
std::vector<T> parse_list(std::string_view name, std::string_view value, std::string_view what, Parse parse) {
  std::vector<T> items;
  for (const std::string& item : split_list(value)) {
    T parsed = parse(item);
    if (std::find(items.begin(), items.end(), parsed) == items.end()) items.push_back(std::move(parsed));
  }
  if (items.empty()) throw UsageError(std::string(name) + " expects a comma-separated list of " + std::string(what));
  return items;
}

// A flag's row: sets `field` of CliOptions (or of a member of it) to true.
template <typename Field>
ApplyOption set_flag(Field field) {
  return [field](std::string_view, CliOptions& options) { field(options) = true; };
}

// Sets a technique option from a names table (parse_choice).
template <typename Enum, std::size_t N>
ApplyOption set_choice(Enum TechniqueOptions::*member, const std::array<std::string_view, N>& names, const char* what,
                       const char* plural) {
  return [member, &names, what, plural](std::string_view value, CliOptions& o) {
    o.technique_options.*member = parse_choice<Enum>(value, names, what, plural);
  };
}

// Every option, each with the code that reads it. One name may appear twice
// when its value means something else in `atrium bench` (a list there).
const std::vector<OptionSpec>& option_table() {
  static const std::vector<OptionSpec> table{
      {"--mode", "M", kWindow | kRender,
       "lighting technique (default: the scene's, 'forward'): " + techniques::technique_names(),
       [](std::string_view value, CliOptions& o) { o.mode = std::string(value); }},
      {"--shading", "S", kDrawing, "shading model: pbr (default), blinn-phong or phong",
       [](std::string_view value, CliOptions& o) {
         o.shading = std::string(value);
         if (lighting::shading_model_index(o.shading) < 0) {
           throw UsageError("unknown shading model '" + o.shading + "' (models: " + lighting::shading_model_names() + ")");
         }
       }},
      {"--cluster-grid", "G", kDrawing | kInfo,
       "clustered modes: square tiles of N pixels and Z depth slices at any size, NpxxZ or Npx (default 24pxx32), "
       "or a fixed number of clusters per axis, XxYxZ (e.g. 16x9x32)",
       [](std::string_view value, CliOptions& o) {
         const std::string text(value);
         const auto bad = [&] { return UsageError("--cluster-grid expects NpxxZ, Npx or XxYxZ (e.g. 24pxx32, 16x9x32), got '" + text + "'"); };
         if (const auto px = text.find("px"); px != std::string::npos) {
           const std::string rest = text.substr(px + 2);
           if (!rest.empty() && !rest.starts_with('x')) throw bad();
           const unsigned tile = parse_number<unsigned>("--cluster-grid", value.substr(0, px), 8, 512);
           const unsigned slices = rest.empty() ? ClusterGridSize{}.dims.z : parse_number<unsigned>("--cluster-grid", rest.substr(1), 2, 256);
           o.technique_options.cluster_grid = ClusterGridSize::pixels(tile, slices);
           return;
         }
         const auto x1 = text.find('x'), x2 = text.find('x', x1 == std::string::npos ? x1 : x1 + 1);
         if (x1 == std::string::npos || x2 == std::string::npos) throw bad();
         o.technique_options.cluster_grid = ClusterGridSize::fixed({parse_number<unsigned>("--cluster-grid", value.substr(0, x1), 1, 256),
                                                                             parse_number<unsigned>("--cluster-grid", value.substr(x1 + 1, x2 - x1 - 1), 1, 256),
                                                                             parse_number<unsigned>("--cluster-grid", value.substr(x2 + 1), 2, 256)});
       }},
      {"--cluster-bounds", "B", kDrawing,
       "clustered modes: test lights against each cluster's box of the pixels it holds (pixels, default) or its "
       "whole frustum slice (grid)",
       set_choice(&TechniqueOptions::cluster_bounds, kClusterBoundsNames, "cluster bounds", "bounds")},
      {"--active-clusters", "", kDrawing, "clustered modes, grid bounds: only clusters holding visible pixels get lights",
       set_flag([](CliOptions& o) -> bool& { return o.technique_options.active_clusters; })},
      {"--light-assignment", "A", kDrawing,
       "tiled and clustered modes: how the light lists are built, scatter (each light visits the bins it may reach), "
       "gather (each bin tests every light) or auto (default: per frame, gather where lights are dense)",
       set_choice(&TechniqueOptions::light_assignment, kLightAssignmentNames, "light assignment", "assignments")},
      {"--material-binding", "B", kDrawing | kInfo,
       "visibility-buffer: how the resolve reaches the materials' textures, bound (one dispatch per material over "
       "the tiles that show it) or bindless (one dispatch over every tile, textures by handle; needs "
       "GL_ARB_bindless_texture) or auto (default: bindless where the context has it)",
       set_choice(&TechniqueOptions::material_binding, kMaterialBindingNames, "material binding", "bindings")},
      {"--z-slicing", "S", kWindow | kRender | kCompare,
       "clustered modes: depth slices log (default: a first slice to ten near-plane distances, then logarithmic), "
       "plain-log (logarithmic from the near plane) or uniform",
       set_choice(&TechniqueOptions::z_slicing, kZSlicingNames, "depth slicing", "slicings")},
      {"--z-slicing", "LIST", kBench, "clustered modes: measure each of these depth slicings (log, plain-log, uniform)",
       [](std::string_view value, CliOptions& o) {
         o.bench.z_slicings = parse_list<ZSlicing>("--z-slicing", value, "slicings", [](const std::string& item) {
           return parse_choice<ZSlicing>(item, kZSlicingNames, "depth slicing", "slicings");
         });
       }},
      {"--gbuffer", "L", kDrawing,
       "deferred modes: G-buffer layout, full (" + gbuffer_size(GBufferLayout::Full) + ", default) or compact (" +
           gbuffer_size(GBufferLayout::Compact) + "; position from depth, octahedral normal)",
       set_choice(&TechniqueOptions::gbuffer_layout, kGBufferLayoutNames, "G-buffer layout", "layouts")},
      {"--split-lighting", "", kDrawing,
       "deferred modes: also write the diffuse and the specular light sums to targets of their own (the "
       "diffuse-light and specular-light views turn this on while shown)",
       set_flag([](CliOptions& o) -> bool& { return o.technique_options.split_lighting; })},
      {"--msaa", "N", kDrawing,
       "multisample anti-aliasing with N = 1 (off, the default), 2, 4 or 8 samples per pixel, up to what the driver "
       "allows; the deferred modes shade per sample only on the edges they mark (debug view msaa-edges), the "
       "visibility buffer each surface a pixel's samples show once (debug view msaa-surfaces)",
       [](std::string_view value, CliOptions& o) {
         // Four values: one message for every other, 3 as 16 or "x".
         if (value != "1" && value != "2" && value != "4" && value != "8") {
           throw UsageError("--msaa expects 1, 2, 4 or 8 samples per pixel, got '" + std::string(value) + "'");
         }
         o.technique_options.msaa = value[0] - '0';
       }},
      {"--shadows", "K", kWindow | kRender | kCompare,
       "shadow maps for the K lights that matter most this frame (0, the default, is off; at most " +
           std::to_string(shadows::kMaxShadowedLights) + "): cube maps for point lights, one map per spot light, cascades for a "
           "directional light, in one atlas; every mode samples them (debug view shadow-atlas)",
       [](std::string_view value, CliOptions& o) { o.shadows = parse_number<int>("--shadows", value, 0, shadows::kMaxShadowedLights); }},
      {"--shadows", "LIST", kBench, "measure with each of these shadowed-light counts (e.g. 0,16,64)",
       [](std::string_view value, CliOptions& o) {
         o.bench.shadow_counts = parse_list<int>("--shadows", value, "shadowed-light counts", [](const std::string& item) {
           return parse_number<int>("--shadows", item, 0, shadows::kMaxShadowedLights);
         });
       }},
      {"--shadow-redraw", "", kBench, "draw every shadow map every frame, as if every light moved (default: maps are reused while nothing in reach moves)",
       set_flag([](CliOptions& o) -> bool& { return o.bench.shadow_redraw; })},
      {"--moving-lights", "", kBench,
       "run the light animation as the demo does (1/60 s a frame): the generated lights of a scene file or model move, "
       "point lights on the GPU where compute shaders run (default: every light holds still)",
       set_flag([](CliOptions& o) -> bool& { return o.bench.moving_lights; })},
      {"--pass-steps", "", kBench,
       "also time the steps inside passes (the light lists' count, scan and write; occlusion culling's pyramid, test and "
       "draws; the material classification's count, ranges and scatter), listed in brackets after their pass (a step that ran in some frames only: its median over those, and in "
       "how many); on a software renderer each step adds two waits for the GPU",
       set_flag([](CliOptions& o) -> bool& { return o.bench.pass_steps; })},
      {"--debug-view", "V", kWindow | kRender,
       "show a debug view: " + render::debug_view_names() +
           ", or any resource the mode's frame graph declares viewable, by its name; `render --debug-view list` "
           "prints the views the mode offers with what each shows; a view the mode does not offer is refused",
       [](std::string_view value, CliOptions& o) {
         // Resource views are known once the mode's graph is built: the
         // renderer refuses a name that is neither, and render and the window
         // a view the mode does not offer (exit 2, listing the mode's views).
         if (value.empty()) throw UsageError("--debug-view needs a view name (see `atrium render --debug-view list`)");
         o.debug_view = std::string(value);
       }},
      {"--lights", "N", kWindow | kRender | kInfo | kCompare,
       "number of lights, 0.." + std::to_string(kMaxLights) +
           " (built-in default: 160); for a scene its listed lights come first, then generated ones; for a glTF "
           "model, N generated lights are added to the model's own",
       [](std::string_view value, CliOptions& o) { o.lights = parse_number<std::uint32_t>("--lights", value, 0, kMaxLights); }},
      {"--lights", "LIST", kBench, "comma-separated light counts to measure (default 10,50,110,1024)",
       [](std::string_view value, CliOptions& o) {
         o.bench.light_counts = parse_list<std::uint32_t>("--lights", value, "light counts", [](const std::string& count) {
           return parse_number<std::uint32_t>("--lights", count, 0, kMaxLights);
         });
       }},
      {"--light-radius", "R", kDrawing,
       "every point and spot light reaches R metres (its intensity scaled to match); bench --constant-density "
       "shrinks R as lights grow",
       [](std::string_view value, CliOptions& o) {
         const std::string text(value);
         char* end = nullptr;
         const float radius = std::strtof(text.c_str(), &end);
         if (end == text.c_str() || *end != '\0' || !(radius > 0.0f) || !std::isfinite(radius)) {
           throw UsageError("--light-radius expects a positive number of metres, got '" + text + "'");
         }
         o.light_radius = radius;
       }},
      {"--max-texture-size", "N", kDrawing | kInfo,
       "textures wider or taller than N pixels are downscaled (default: what the GL context allows, "
       "GL_MAX_TEXTURE_SIZE)",
       [](std::string_view value, CliOptions& o) { o.max_texture_size = parse_number<int>("--max-texture-size", value, 1, 65536); }},
      {"--view", "K", kWindow | kRender, "stored view 1..5 (default 1)",
       [](std::string_view value, CliOptions& o) { o.view = parse_number<int>("--view", value, 1, 1000); }},
      {"--camera", "X,Y,Z,YAW,PITCH", kDrawing,
       "look from here instead of the stored views (metres; degrees, yaw 0 looks along -Z, 90 along +X; pitch up > "
       "0). The window's c key prints the camera.",
       [](std::string_view value, CliOptions& o) {
         o.camera = assets::parse_camera_argument(value);
         if (!o.camera) {
           throw UsageError("--camera expects X,Y,Z,YAW,PITCH (metres, then degrees; pitch from -90 to 90), got '" +
                            std::string(value) + "'");
         }
       }},
      {"--size", "WxH", kDrawing | kInfo | kProbe,
       "image or window size in pixels (default 1280x720; compare and bench: 320x180; info: for --memory; probe: 1920x1080)",
       [](std::string_view value, CliOptions& o) { o.size = parse_size(value); }},
      {"--out", "FILE.png", kRender, "where to write the image", [](std::string_view value, CliOptions& o) { o.out = std::string(value); }},
      {"--frames", "N", kWindow, "quit after N frames (for scripted runs)",
       [](std::string_view value, CliOptions& o) { o.frames = parse_number<std::uint64_t>("--frames", value, 1, 1'000'000'000); }},
      {"--frames", "N", kBench, "frames measured per run (default 30)",
       [](std::string_view value, CliOptions& o) { o.bench.frames = parse_number<int>("--frames", value, 1, 100000); }},
      {"--warmup", "N", kBench, "frames drawn before measuring each run (default 5)",
       [](std::string_view value, CliOptions& o) { o.bench.warmup = parse_number<int>("--warmup", value, 0, 100000); }},
      {"--frame-limit", "MS", kBench,
       "a run stops after a frame slower than MS milliseconds (10x MS for its first frame, which compiles programs), "
       "and the mode is skipped at larger light counts that pass it, or that would pass 4x MS if its time grew with "
       "the lights (default 1000, in whole milliseconds; the table says why)",
       [](std::string_view value, CliOptions& o) { o.bench.frame_limit_ms = parse_number<int>("--frame-limit", value, 1, 10000000); }},
      {"--modes", "all|LIST", kBench, "the modes to measure (default all)",
       [](std::string_view value, CliOptions& o) {
         o.bench.modes.clear();
         if (value == "all") return;
         o.bench.modes = parse_list<std::string>("--modes", value, "modes (or all)", [](const std::string& mode) {
           if (!techniques::find_technique(mode)) {
             throw UsageError("unknown mode '" + mode + "' in --modes (modes: " + techniques::technique_names() + ")");
           }
           return mode;
         });
       }},
      {"--views", "all|LIST", kBench, "the stored views to measure from (default all)",
       [](std::string_view value, CliOptions& o) {
         o.bench.views.clear();
         if (value == "all") return;
         for (const std::string& view : split_list(value)) o.bench.views.push_back(parse_number<int>("--views", view, 1, 1000));
       }},
      {"--constant-density", "", kBench, "shrink the light radius as the light count grows, keeping lights per pixel level",
       set_flag([](CliOptions& o) -> bool& { return o.bench.constant_density; })},
      {"--csv", "FILE", kBench, "write the results as CSV", [](std::string_view value, CliOptions& o) { o.csv = std::string(value); }},
      {"--md", "FILE", kBench, "write the results as a Markdown table", [](std::string_view value, CliOptions& o) { o.md = std::string(value); }},
      {"--plot", "FILE.png", kBench, "plot frame time against light count (python3 with matplotlib)",
       [](std::string_view value, CliOptions& o) { o.plot = std::string(value); }},
      {"--gl-debug", "", kWindow, "report GL errors through KHR_debug and print their count on exit (always on in debug builds)",
       set_flag([](CliOptions& o) -> bool& { return o.gl_debug; })},
      {"--no-culling", "", kDrawing, "draw the whole scene in every pass (frustum, back-facing meshlet and occlusion culling are on by default)",
       [](std::string_view, CliOptions& o) { o.frustum_culling = false; }},
      {"--poison-targets", "", kWindow | kRender,
       "for authors of passes: fill each frame target with a marker (magenta, 0xdeadbeef, depth 0.5) before the pass "
       "that writes it first, so that texels a pass leaves unwritten show (compare always does)",
       set_flag([](CliOptions& o) -> bool& { return o.poison_targets; })},
      {"--no-occlusion-culling", "", kDrawing, "draw what is in view even where the depth buffer hides it (occlusion culling is on by default)",
       [](std::string_view, CliOptions& o) { o.occlusion_culling = false; }},
      {"--culling", "WHERE", kDrawing,
       "where occlusion culling tests what the depth hides: cpu (depth read back each frame), gpu (nothing read back) or auto "
       "(default: cpu on a software renderer, where it is faster, gpu elsewhere)",
       [](std::string_view value, CliOptions& o) {
         for (const CullingDeviceName& row : kCullingDevices) {
           if (row.name == value) {
             o.culling_device = row.device;
             return;
           }
         }
         throw UsageError("unknown --culling '" + std::string(value) + "' (expected auto, cpu or gpu)");
       }},
      {"--lighting-stage", "S", kWindow | kRender,
       "where the full-screen passes run (the deferred modes' lighting, every mode's tone map): fragment (full-screen "
       "triangles), compute (one invocation per pixel, stored with imageStore, with MSAA the edges' samples shared out "
       "over the work group; not with --no-compute) or auto (default, or the scene file's \"lighting_stage\": compute on "
       "GPUs, fragment on software renderers and on the compute-free tier)",
       [](std::string_view value, CliOptions& o) { o.lighting_stage = parse_lighting_stage(value); }},
      {"--lighting-stage", "LIST", kCompare | kBench,
       "measure each of these stages (fragment, compute, auto; compare: default fragment,compute, leaving out a stage the "
       "context cannot run; bench: default auto)",
       [](std::string_view value, CliOptions& o) {
         o.lighting_stages = parse_list<LightingStage>("--lighting-stage", value, "stages", parse_lighting_stage);
       }},
      {"--no-compute", "", kDrawing | kInfo,
       "run on the compute-free tier, as on WebGL2 or OpenGL 4.1: no compute shaders or storage buffers (lights, instances "
       "and materials in textures, draws issued one by one, tiled and clustered light lists binned on the CPU, no occlusion "
       "culling); every mode and shadow maps run there, the counting debug views (heatmap, fragments) do not",
       [](std::string_view, CliOptions& o) { o.technique_options.compute_free = true; }},
      {"--gl", "API", kDrawing | kInfo,
       "which OpenGL to ask the driver for: 4.5 (core), 4.1 (core, where macOS stops), es3.0 (OpenGL ES 3.0, WebGL2's "
       "feature set) or auto (default: the first of those the driver gives); a context without compute shaders or storage "
       "buffers runs the compute-free tier by itself (see --no-compute)",
       [](std::string_view value, CliOptions& o) {
         const auto api = gfx::gl_api_from_name(value);
         if (!api) throw UsageError("unknown --gl '" + std::string(value) + "' (expected auto, 4.5, 4.1 or es3.0)");
         o.gl_api = *api;
       }},
      {"--json", "", kInfo | kProbe, "print JSON", set_flag([](CliOptions& o) -> bool& { return o.json; })},
      {"--memory", "", kInfo,
       "draw one frame of every mode at --size and report its render-target memory: long-lived targets, and transient "
       "ones with and without sharing GL objects where their lifetimes do not overlap",
       set_flag([](CliOptions& o) -> bool& { return o.memory; })},
  };
  static const std::vector<OptionSpec> with_systems = [] {
    std::vector<OptionSpec> rows = table;
    for (const SystemOptionSpec& s : kSystemOptions) {
      rows.push_back({std::string(s.name), std::string(s.value), kDrawing, std::string(s.help),
                      [s](std::string_view value, CliOptions& o) {
                        o.system_options[std::string(s.name.substr(2))] =
                            s.whole ? parse_number<int>(s.name, value, static_cast<int>(s.min), static_cast<int>(s.max))
                                    : parse_number<double>(s.name, value, s.min, s.max);
                      }});
    }
    return rows;
  }();
  return with_systems;
}

// "the window and `atrium render`": the commands in `commands`, for messages and help.
std::string command_list(unsigned commands) {
  std::vector<std::string> names;
  for (const CommandSpec& c : kCommands) {
    if (commands & on(c.command)) names.push_back(c.name.empty() ? "the window" : "`atrium " + std::string(c.name) + "`");
  }
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i) {
    text += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
  }
  return text;
}

// `text` wrapped to kWidth columns, its first line starting at column `first`
// and the others at `indent`.
std::string wrap(std::string_view text, std::size_t first, std::size_t indent) {
  constexpr std::size_t kWidth = 92;
  std::string out;
  std::size_t column = first;
  bool line_start = true;
  for (std::size_t start = 0; start < text.size();) {
    std::size_t end = text.find(' ', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view word = text.substr(start, end - start);
    if (!line_start && column + 1 + word.size() > kWidth) {
      out += "\n" + std::string(indent, ' ');
      column = indent;
      line_start = true;
    }
    if (!line_start) {
      out += ' ';
      ++column;
    }
    out += word;
    column += word.size();
    line_start = false;
    start = end + 1;
  }
  return out + "\n";
}

// "  --view K        stored view 1..5": the help column starts at kColumn, or two
// spaces after a long option.
std::string option_help(const OptionSpec& option, bool tag_commands) {
  constexpr std::size_t kColumn = 18;
  std::string head = "  " + option.name + (option.value.empty() ? "" : " " + option.value);
  head += std::string(head.size() + 2 <= kColumn ? kColumn - head.size() : 2, ' ');
  std::string help = option.help;
  if (tag_commands && (option.commands & kDrawing) != kDrawing) {
    std::string names;
    for (const CommandSpec& c : kCommands) {
      if (option.commands & on(c.command)) names += (names.empty() ? "" : ", ") + std::string(c.name.empty() ? "window" : c.name);
    }
    help = "[" + names + "] " + help;
  }
  return head + wrap(help, head.size(), kColumn);
}

// One option given on the command line, already known to belong to the command.
void apply_option(std::string_view name, std::string_view value, CliOptions& options) {
  for (const OptionSpec& option : option_table()) {
    if (option.name == name && (option.commands & on(options.command))) return option.apply(value, options);
  }
  throw std::logic_error("no option row reads " + std::string(name));
}

// Edit distance with adjacent transpositions: how far a misspelt option is from a real one.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    for (std::size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] != b[j - 1])});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  }
  return d[a.size()][b.size()];
}

// The refusal of `argument`, an option the command does not take: which
// commands do take it, or the nearest option this one does.
UsageError unknown_option(std::string_view argument, Command command) {
  const std::string name(argument.substr(0, argument.find('=')));
  if (command == Command::Compare && name == "--mode") return UsageError("compare renders every mode; --mode does not apply");
  unsigned elsewhere = 0;
  for (const OptionSpec& option : option_table()) elsewhere |= option.name == name ? option.commands : 0u;
  if (elsewhere != 0) return UsageError(name + " is for " + command_list(elsewhere));
  const CommandSpec& spec = command_spec(command);
  const std::string help = spec.name.empty() ? "atrium --help" : "atrium " + std::string(spec.name) + " --help";
  std::string nearest;
  std::size_t best = std::max<std::size_t>(2, name.size() / 4) + 1;
  for (const OptionSpec& option : option_table()) {
    if (!(option.commands & on(command))) continue;
    const std::size_t distance = edit_distance(name, option.name);
    if (distance < best) best = distance, nearest = option.name;
  }
  if (!nearest.empty()) return UsageError("unknown option '" + name + "' (did you mean " + nearest + "? see " + help + ")");
  return UsageError("unknown option '" + name + "' (see " + help + ")");
}

// Every option and the scene on `app`, which parses the command line of `command`.
void declare(CLI::App& app, Command command) {
  app.allow_extras();  // refused below, with the message the user needs
  for (const OptionSpec& option : option_table()) {
    if (!(option.commands & on(command))) continue;
    CLI::Option* added = option.value.empty() ? app.add_flag(option.name) : app.add_option(option.name);
    if (!option.value.empty()) added->type_name(option.value);
    // The GNU convention: a repeated option's last value wins.
    added->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  }
  app.add_option("scene");
}

// The arguments `app` took, as (name, value) in the table's order; the scene as "scene".
void collect(const CLI::App& app, std::vector<std::pair<std::string, std::string>>& given) {
  for (const CLI::Option* option : app.get_options()) {
    if (option->count() == 0 || option->get_name() == "--help" || option->get_name() == "-h") continue;
    const std::string name = option->get_positional() ? "scene" : option->get_name();
    given.emplace_back(name, option->get_expected_min() == 0 ? std::string() : option->results().back());
  }
}

}  // namespace

std::string help_text(Command command) {
  if (command == Command::Window || command == Command::Help || command == Command::Version) {
    std::string text = "Usage:\n";
    for (const CommandSpec& c : kCommands) {
      text += "  " + std::string(c.usage) + "\n" + std::string(4, ' ') + wrap(c.summary, 4, 4);
    }
    text += "  atrium --version                          print the version\n"
            "  atrium [COMMAND] --help                   this text, or one command's options\n"
            "\n"
            + wrap("SCENE is the built-in scene 'atrium' (the default), a scene file (scenes/*.json, see "
                   "docs/scene-format.md) or a model file: " + assets::model_formats_text() + ".", 0, 0) +
            "Options take their value as `--opt value` or `--opt=value`; the last one given wins.\n"
            "\n"
            "Options ([render, bench]: only for those commands; the others are for every command that draws):\n";
    for (const OptionSpec& option : option_table()) text += option_help(option, true);
    std::string modes;
    for (const auto& info : techniques::technique_table()) {
      constexpr std::size_t kColumn = 26;
      const std::size_t padding = info.name.size() + 2 < kColumn ? kColumn - info.name.size() : 2;
      modes += "  " + std::string(info.name) + std::string(padding, ' ') + std::string(info.description) + "\n";
    }
    return text + "\nModes:\n" + modes + "\nWindow keys:\n" + window_key_help() +
           "\nExit codes: 0 success, 1 runtime failure (no GL context, shader error, a frame the\n"
           "driver cannot hold: the message names the limit), 2 bad usage or bad input.\n";
  }
  const CommandSpec& spec = command_spec(command);
  std::string text = "Usage: " + std::string(spec.usage) + "\n" + wrap(spec.summary, 0, 0) + "\nOptions:\n";
  for (const OptionSpec& option : option_table()) {
    if (option.commands & on(command)) text += option_help(option, false);
  }
  return text + "  --help          this text\n\nSCENE and the modes: atrium --help.\n";
}

std::string version_text() { return std::string("atrium ") + ATRIUM_VERSION + "\n"; }

CliOptions parse_cli(std::span<const std::string_view> args) {
  CLI::App app("", "atrium");
  declare(app, Command::Window);
  app.add_flag("--version");
  std::vector<std::pair<CLI::App*, Command>> commands;
  for (const CommandSpec& spec : kCommands) {
    if (spec.name.empty()) continue;
    CLI::App* sub = app.add_subcommand(std::string(spec.name), std::string(spec.summary));
    declare(*sub, spec.command);
    commands.emplace_back(sub, spec.command);
  }
  app.require_subcommand(0, 1);

  CliOptions options;
  auto chosen = [&]() -> std::pair<const CLI::App*, Command> {
    for (const auto& [sub, command] : commands) {
      if (sub->parsed()) return {sub, command};
    }
    return {&app, Command::Window};
  };
  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes them last first
  try {
    app.parse(reversed);
  } catch (const CLI::CallForHelp&) {
    options.command = Command::Help;
    options.help_topic = chosen().second;
    return options;
  } catch (const CLI::ArgumentMismatch& e) {
    // CLI11 words a missing value "--view: 1 required K missing".
    const std::string what = e.what();
    const std::size_t colon = what.find(':');
    if (colon != std::string::npos && what.ends_with(" missing")) throw UsageError(what.substr(0, colon) + " needs a value");
    throw UsageError(what);
  } catch (const CLI::ParseError& e) {
    throw UsageError(e.what());
  }
  if (app.get_option("--version")->count() > 0) {
    options.command = Command::Version;
    return options;
  }
  const auto [parsed, command] = chosen();
  options.command = command;
  if (command == Command::Bench || command == Command::Compare) options.size = {320, 180};
  if (command == Command::Probe) options.size = {1920, 1080};
  for (const std::string& extra : app.remaining(true)) {
    if (extra == "--") continue;
    if (extra.starts_with("-")) throw unknown_option(extra, command);
    throw UsageError("unexpected argument '" + extra + "' (one scene at most)");
  }

  std::vector<std::pair<std::string, std::string>> given;
  collect(app, given);
  if (parsed != &app) {
    // Options before the command's name belong to the window's parser; the
    // command must take them too.
    for (const auto& [name, value] : given) {
      if (name != "scene" && name != "--version" && parsed->get_option_no_throw(name) == nullptr) {
        throw unknown_option(name, command);
      }
    }
    collect(*parsed, given);
  }
  bool scene_given = false;
  for (const auto& [name, value] : given) {
    if (name == "scene") {
      if (scene_given) throw UsageError("unexpected argument '" + value + "' (one scene at most)");
      options.scene = value;
      scene_given = true;
    } else if (name != "--version") {
      apply_option(name, value, options);
    }
  }

  if (options.debug_view == "list" && options.command != Command::Render) {
    throw UsageError("--debug-view list is for `atrium render` (atrium render --mode M --debug-view list)");
  }
  if (options.command == Command::Render && options.out.empty() && options.debug_view != "list") {
    throw UsageError("render needs --out FILE.png");
  }
  if (options.lighting_stage == LightingStage::Compute) {
    // A combination that can never run is bad usage, refused before any context.
    TechniqueOptions asked = options.technique_options;
    asked.lighting_stage = *options.lighting_stage;
    try {
      (void)lighting::resolve_lighting_stage(asked);
    } catch (const gfx::ResourceLimitError& e) {
      throw UsageError(e.what());
    }
  }
  if (options.command == Command::Probe && scene_given) throw UsageError("probe draws no scene; '" + options.scene + "' does not apply");
  if (options.camera && options.view != 1) throw UsageError("--camera replaces the scene's views; --view does not apply");
  if (options.camera && options.command == Command::Bench && options.bench.views.size() > 0) {
    throw UsageError("--camera replaces the scene's views; --views does not apply");
  }
  if (options.mode) {
    try {
      require_known_mode(*options.mode);
    } catch (const InputError& e) {
      throw UsageError(e.what());
    }
  }
  return options;
}

WorldOptions world_options(const CliOptions& options) {
  return {.scene = options.scene,
          .lights = options.lights,
          .mode = options.mode,
          .view = options.view,
          .size = options.size,
          .shading = options.shading,
          .debug_view = options.debug_view,
          .technique_options = options.technique_options,
          .light_radius = options.light_radius,
          .max_texture_size = options.max_texture_size,
          .camera = options.camera,
          .frustum_culling = options.frustum_culling,
          .shadows = options.shadows,
          .occlusion_culling = options.occlusion_culling,
          .culling_device = options.culling_device,
          .poison_targets = options.poison_targets,
          .lighting_stage = options.lighting_stage,
          .system_options = options.system_options};
}


}  // namespace atrium
