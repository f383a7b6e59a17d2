#include "app/cli.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdlib>
#include <fstream>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <vector>

#include "app/info.hpp"
#include "app/progress_bar.hpp"
#include "app/world.hpp"
#include "components/frame_resources.hpp"
#include "assets/image.hpp"
#include "gfx/context.hpp"
#include "gfx/shader_program.hpp"
#include "systems/overlay.hpp"
#include "systems/lighting/debug_views.hpp"
#include "systems/lighting/shading_model.hpp"
#include "systems/lighting/technique.hpp"

namespace atrium {
namespace {

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
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || value < min || value > max) {
    throw UsageError(std::string(flag) + " expects a whole number from " + std::to_string(min) + " to " +
                     std::to_string(max) + ", got '" + std::string(text) + "'");
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

// The options only `atrium bench` has, or whose meaning differs there
// (--lights takes a list). Returns false for an option that is not one.
template <typename Value>
bool parse_bench_option(std::string_view arg, Value&& value, CliOptions& options) {
  BenchOptions& bench = options.bench;
  if (arg == "--modes") {
    const std::string_view text = value();
    bench.modes.clear();
    if (text != "all") {
      for (const std::string& mode : split_list(text)) {
        if (!lighting::find_technique(mode)) {
          throw UsageError("unknown mode '" + mode + "' in --modes (modes: " + lighting::technique_names() + ")");
        }
        bench.modes.push_back(mode);
      }
      if (bench.modes.empty()) throw UsageError("--modes expects all or a comma-separated list of modes");
    }
  } else if (arg == "--lights") {
    bench.light_counts.clear();
    for (const std::string& count : split_list(value())) {
      bench.light_counts.push_back(parse_number<std::uint32_t>("--lights", count, 0, kMaxLights));
    }
    if (bench.light_counts.empty()) throw UsageError("--lights expects a comma-separated list of light counts");
  } else if (arg == "--views") {
    const std::string_view text = value();
    bench.views.clear();
    if (text != "all") {
      for (const std::string& view : split_list(text)) bench.views.push_back(parse_number<int>("--views", view, 1, 1000));
    }
  } else if (arg == "--z-slicing") {
    bench.z_slicings.clear();
    for (const std::string& name : split_list(value())) {
      const auto slicing = parse_choice<lighting::ZSlicing>(name, lighting::kZSlicingNames, "depth slicing", "slicings");
      if (std::find(bench.z_slicings.begin(), bench.z_slicings.end(), slicing) == bench.z_slicings.end()) {
        bench.z_slicings.push_back(slicing);
      }
    }
    if (bench.z_slicings.empty()) throw UsageError("--z-slicing expects a comma-separated list of slicings");
  } else if (arg == "--frames") {
    bench.frames = parse_number<int>("--frames", value(), 1, 100000);
  } else if (arg == "--warmup") {
    bench.warmup = parse_number<int>("--warmup", value(), 0, 100000);
  } else if (arg == "--constant-density") {
    bench.constant_density = true;
  } else if (arg == "--csv") {
    options.csv = std::string(value());
  } else if (arg == "--md") {
    options.md = std::string(value());
  } else if (arg == "--plot") {
    options.plot = std::string(value());
  } else {
    return false;
  }
  return true;
}

}  // namespace

std::string help_text() {
  std::string modes;
  for (const auto& info : lighting::technique_table()) {
    constexpr std::size_t kColumn = 26;
    const std::size_t padding = info.name.size() + 2 < kColumn ? kColumn - info.name.size() : 2;
    modes += "  " + std::string(info.name) + std::string(padding, ' ') + std::string(info.description) + "\n";
  }
  return "Usage:\n"
         "  atrium [SCENE] [options]                 open the demo window\n"
         "  atrium render [SCENE] --out FILE.png [options]\n"
         "                                           render one frame headless to a PNG\n"
         "  atrium info [SCENE] [--json]             what the scene holds and what loading cost\n"
         "  atrium compare [SCENE] [--size WxH] [--lights N] [--shading S] [--gbuffer L]\n"
         "                                           every mode at every view against forward (PSNR,\n"
         "                                           largest difference); exit 1 under 40 dB\n"
         "  atrium bench [SCENE] [--modes all|LIST] [--lights LIST] [--views all|LIST] [--size WxH]\n"
         "               [--frames N] [--warmup N] [--constant-density] [--z-slicing LIST]\n"
         "               [--csv FILE] [--md FILE] [--plot FILE.png]\n"
         "                                           frame and pass times over modes, light counts\n"
         "                                           and views (default: all modes, 10,50,110,1024\n"
         "                                           lights, all views, 320x180, 30 frames, 5 warm-up)\n"
         "  atrium --help                            show this text\n"
         "\n"
         "SCENE is the built-in scene 'atrium' (the default), a scene file (scenes/*.json,\n"
         "see docs/scene-format.md) or a model file: glTF (.gltf, .glb), OBJ, FBX and the other\n"
         "formats libassimp reads (.dae, .3ds, .ply, .stl, .x, .lwo, .ase, .off).\n"
         "\n"
         "Options:\n"
         "  --mode M        lighting technique (default: the scene's, 'forward')\n"
         "  --shading S     shading model: pbr (default), blinn-phong or phong\n"
         "  --cluster-grid XxYxZ  clustered modes: clusters per axis (default 16x9x32)\n"
         "  --cluster-bounds B    clustered modes: test lights against each cluster's box of the\n"
         "                  pixels it holds (pixels, default) or its whole frustum slice (grid)\n"
         "  --active-clusters     clustered modes, grid bounds: only clusters holding visible\n"
         "                  pixels get lights\n"
         "  --z-slicing S   clustered modes: depth slices log (default: a first slice to ten\n"
         "                  near-plane distances, then logarithmic), plain-log (logarithmic from\n"
         "                  the near plane) or uniform; bench takes a list and measures each\n"
         "  --gbuffer L     deferred modes: G-buffer layout, full (5 targets, 44 B/px, default)\n"
         "                  or compact (2 targets, 24 B/px; position from depth, octahedral normal)\n"
         "  --split-lighting  deferred modes: also write the diffuse and the specular light\n"
         "                  sums to targets of their own (the diffuse-light and specular-light\n"
         "                  views turn this on while shown)\n"
         "  --debug-view V  render or window: show position, normal, albedo, metallic-roughness,\n"
         "                  emissive, depth, light-volumes (outlines), heatmap (lights\n"
         "                  evaluated per pixel in the current mode), light-lists (lights in\n"
         "                  each pixel's tile or cluster list), depth-slices (cluster slices)\n"
         "                  fragments (fragments the mode's geometry passes rasterise per\n"
         "                  pixel: overdraw, a camera in foliage), diffuse-light or\n"
         "                  specular-light (deferred modes: the two light sums apart),\n"
         "                  light-buffer (light-prepass: light summed before materials)\n"
         "  --lights N      number of lights, 0.." + std::to_string(kMaxLights) + " (built-in default: 160); for a\n"
         "                  scene its listed lights come first, then generated ones; for a glTF\n"
         "                  model, N generated lights are added to the model's own\n"
         "  --light-radius R  every point and spot light reaches R metres (its intensity\n"
         "                  scaled to match); bench --constant-density shrinks R as lights grow\n"
         "  --max-texture-size N  textures wider or taller than N pixels are downscaled\n"
         "                  (default: what the GL context allows, GL_MAX_TEXTURE_SIZE)\n"
         "  --view K        stored view 1..5 (default 1)\n"
         "  --camera X,Y,Z,YAW,PITCH  render, compare, bench, window: look from here instead\n"
         "                  of the stored views (metres; degrees, yaw 0 looks along -Z, 90\n"
         "                  along +X; pitch up > 0). The window's c key prints the camera.\n"
         "  --size WxH      image or window size in pixels (default 1280x720)\n"
         "  --out FILE.png  render: where to write the image\n"
         "  --frames N      window: quit after N frames (for scripted runs)\n"
         "  --gl-debug      window: report GL errors through KHR_debug and print their count\n"
         "                  on exit (always on in debug builds)\n"
         "  --no-culling    render, compare, bench, window: draw the whole scene in every pass\n"
         "                  (frustum and back-facing meshlet culling are on by default)\n"
         "  --json          info: print JSON\n"
         "\n"
         "Modes:\n" + modes +
         "\n"
         "Window keys:\n" + key_help() +
         "\nExit codes: 0 success, 1 runtime failure (no GL context, shader error, a frame the\n"
         "driver cannot hold: the message names the limit), 2 bad usage or bad input.\n";
}

CliOptions parse_cli(std::span<const std::string_view> args) {
  CliOptions options;
  std::size_t i = 0;
  if (i < args.size() && args[i] == "render") {
    options.command = Command::Render;
    ++i;
  } else if (i < args.size() && args[i] == "info") {
    options.command = Command::Info;
    ++i;
  } else if (i < args.size() && args[i] == "bench") {
    options.command = Command::Bench;
    options.size = {320, 180};
    ++i;
  } else if (i < args.size() && args[i] == "compare") {
    options.command = Command::Compare;
    options.size = {320, 180};
    ++i;
  }
  bool scene_given = false;
  bool out_given = false;
  for (; i < args.size(); ++i) {
    const std::string_view arg = args[i];
    if (arg == "--help" || arg == "-h") {
      options.command = Command::Help;
      return options;
    }
    auto value = [&]() -> std::string_view {
      if (i + 1 >= args.size()) throw UsageError(std::string(arg) + " needs a value");
      return args[++i];
    };
    if (options.command == Command::Bench && parse_bench_option(arg, value, options)) continue;
    if (arg == "--mode") {
      options.mode = std::string(value());
    } else if (arg == "--cluster-grid") {
      const std::string text(value());
      const auto x1 = text.find('x'), x2 = text.find('x', x1 == std::string::npos ? x1 : x1 + 1);
      if (x1 == std::string::npos || x2 == std::string::npos) {
        throw UsageError("--cluster-grid expects XxYxZ (e.g. 16x9x24), got '" + text + "'");
      }
      options.technique_options.cluster_grid = {
          parse_number<unsigned>("--cluster-grid", std::string_view(text).substr(0, x1), 1, 256),
          parse_number<unsigned>("--cluster-grid", std::string_view(text).substr(x1 + 1, x2 - x1 - 1), 1, 256),
          parse_number<unsigned>("--cluster-grid", std::string_view(text).substr(x2 + 1), 2, 256)};
    } else if (arg == "--active-clusters") {
      options.technique_options.active_clusters = true;
    } else if (arg == "--cluster-bounds") {
      options.technique_options.cluster_bounds =
          parse_choice<lighting::ClusterBounds>(value(), lighting::kClusterBoundsNames, "cluster bounds", "bounds");
    } else if (arg == "--z-slicing") {
      options.technique_options.z_slicing =
          parse_choice<lighting::ZSlicing>(value(), lighting::kZSlicingNames, "depth slicing", "slicings");
    } else if (arg == "--split-lighting") {
      options.technique_options.split_lighting = true;
    } else if (arg == "--gbuffer") {
      options.technique_options.gbuffer_layout =
          parse_choice<lighting::GBufferLayout>(value(), lighting::kGBufferLayoutNames, "G-buffer layout", "layouts");
    } else if (arg == "--debug-view") {
      options.debug_view = std::string(value());
      if (lighting::debug_view_index(options.debug_view) < 0) {
        throw UsageError("unknown debug view '" + options.debug_view + "' (views: " + lighting::debug_view_names() + ")");
      }
    } else if (arg == "--shading") {
      options.shading = std::string(value());
      if (lighting::shading_model_index(options.shading) < 0) {
        throw UsageError("unknown shading model '" + options.shading + "' (models: " + lighting::shading_model_names() + ")");
      }
    } else if (arg == "--lights") {
      options.lights = parse_number<std::uint32_t>("--lights", value(), 0, kMaxLights);
    } else if (arg == "--light-radius") {
      const std::string text(value());
      char* end = nullptr;
      const float radius = std::strtof(text.c_str(), &end);
      if (end == text.c_str() || *end != '\0' || !(radius > 0.0f) || !std::isfinite(radius)) {
        throw UsageError("--light-radius expects a positive number of metres, got '" + text + "'");
      }
      options.light_radius = radius;
    } else if (arg == "--max-texture-size") {
      options.max_texture_size = parse_number<int>("--max-texture-size", value(), 1, 65536);
    } else if (arg == "--view") {
      options.view = parse_number<int>("--view", value(), 1, 1000);
    } else if (arg == "--camera") {
      const std::string_view text = value();
      options.camera = assets::parse_camera_argument(text);
      if (!options.camera) {
        throw UsageError("--camera expects X,Y,Z,YAW,PITCH (metres, then degrees; pitch from -90 to 90), got '" + std::string(text) + "'");
      }
    } else if (arg == "--size") {
      options.size = parse_size(value());
    } else if (arg == "--out") {
      options.out = std::string(value());
      out_given = true;
    } else if (arg == "--json") {
      if (options.command != Command::Info) throw UsageError("--json is for `atrium info`");
      options.json = true;
    } else if (arg == "--frames") {
      options.frames = parse_number<std::uint64_t>("--frames", value(), 1, 1'000'000'000);
    } else if (arg == "--no-culling") {
      options.frustum_culling = false;
    } else if (arg == "--gl-debug") {
      options.gl_debug = true;
    } else if (arg.starts_with("-")) {
      throw UsageError("unknown option '" + std::string(arg) + "' (see atrium --help)");
    } else if (!scene_given) {
      options.scene = std::string(arg);
      scene_given = true;
    } else {
      throw UsageError("unexpected argument '" + std::string(arg) + "' (one scene at most)");
    }
  }
  if (options.command == Command::Render && !out_given) throw UsageError("render needs --out FILE.png");
  if (options.command != Command::Render && out_given) throw UsageError("--out is for `atrium render`");
  if (options.command == Command::Compare && options.mode) throw UsageError("compare renders every mode; --mode does not apply");
  if (!options.debug_view.empty() && options.command != Command::Render && options.command != Command::Window) {
    throw UsageError("--debug-view is for `atrium render` and the window");
  }
  if (options.command != Command::Window && options.frames) throw UsageError("--frames is for the window");
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
  return {options.scene, options.lights,     options.mode,       options.view,
          options.size,  options.shading,    options.debug_view, options.technique_options,
          options.light_radius, options.max_texture_size, options.camera, options.frustum_culling};
}

namespace {

int run_render(const CliOptions& options) {
  const std::filesystem::path out(options.out);
  if (out.has_parent_path() && !std::filesystem::is_directory(out.parent_path())) {
    throw InputError(options.out + ": the folder " + out.parent_path().string() + " does not exist");
  }
  const auto context = gfx::HeadlessContext::create();
  World world(world_options(options));
  world.frame(0.0);
  // The first frame sizes the light lists (and shows them as overflowed);
  // the light-lists view is meant to show them as they settle.
  if (options.debug_view == "light-lists") world.frame(0.0);
  assets::write_png(out, world.renderer().read_output());
  const FrameStats& stats = world.renderer().stats();
  std::printf("wrote %s (%dx%d, mode %s, view %d '%s', %u lights, %zu triangles drawn of %zu in %zu draws, %s)\n",
              options.out.c_str(), options.size.x, options.size.y, world.mode().c_str(), world.view(),
              world.scene().views[static_cast<std::size_t>(world.view() - 1)].name.c_str(), stats.lights,
              stats.triangles_drawn, stats.triangles, stats.draw_calls, context->info().renderer.c_str());
  if (options.debug_view == "heatmap") {
    std::printf("light evaluations per pixel: %.2f on average\n", stats.light_evaluations_per_pixel);
  }
  if (options.debug_view == "fragments") {
    std::printf("fragments rasterised per pixel by the geometry passes: %.2f on average\n", stats.fragments_per_pixel);
  }
  if (world.renderer().timer().counts_fragments()) {
    // The frame's fragments per pass: overdraw and expensive cameras show here.
    std::string passes;
    const double pixels = static_cast<double>(options.size.x) * options.size.y;
    for (const gfx::PassTime& pass : world.renderer().timer().latest()) {
      char text[96];
      std::snprintf(text, sizeof text, "%s%s %.2f", passes.empty() ? "" : ", ", pass.name.c_str(), static_cast<double>(pass.fragments) / pixels);
      passes += text;
    }
    std::printf("fragments shaded per pixel: %s\n", passes.c_str());
  }
  if (stats.light_list_entries > 0) {
    std::printf("light lists: %u entries, %u overflowed frames (the list grew and was filled again)\n",
                stats.light_list_entries, stats.light_list_overflows);
  }
  return kExitOk;
}

}  // namespace

int run_info(const CliOptions& options) {
  const auto context = gfx::HeadlessContext::create();
  WorldOptions loaded = world_options(options);
  loaded.size = {16, 16};  // info renders nothing worth a large target
  World world(loaded);
  const SceneInfo info = gather_info(world, options.scene);
  std::fputs((options.json ? format_info_json(info) : format_info_text(info)).c_str(), stdout);
  return kExitOk;
}

// Every mode at every view against forward: PSNR and largest channel difference.
int run_compare(const CliOptions& options) {
  const auto context = gfx::HeadlessContext::create();
  WorldOptions compared = world_options(options);
  compared.mode = "forward";
  World world(compared);
  std::printf("%-24s %-18s %10s %9s\n", "mode", "view", "PSNR", "max diff");
  bool all_close = true;
  for (int view = 1; view <= static_cast<int>(world.scene().views.size()); ++view) {
    world.set_view(view);
    world.set_mode("forward");
    world.frame(0.0);
    const assets::Image reference = world.renderer().read_output();
    const std::string view_name = std::to_string(view) + " " + world.scene().views[static_cast<std::size_t>(view - 1)].name;
    for (const auto& technique : lighting::technique_table()) {
      if (technique.name == "forward") continue;
      world.set_mode(std::string(technique.name));
      world.frame(0.0);
      const assets::Image image = world.renderer().read_output();
      const double psnr = assets::psnr(reference, image);
      const bool close = psnr >= kMinimumPsnr;
      all_close = all_close && close;
      std::printf("%-24s %-18s %7.2f dB %9d%s\n", std::string(technique.name).c_str(), view_name.c_str(),
                  std::isinf(psnr) ? 999.99 : psnr, assets::max_channel_difference(reference, image), close ? "" : "  < 40 dB");
    }
  }
  std::printf(all_close ? "every mode is within %.0f dB PSNR of forward\n" : "some modes differ from forward by more than %.0f dB PSNR\n",
              kMinimumPsnr);
  return all_close ? kExitOk : kExitRuntimeFailure;
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  if (!out) throw InputError(path + ": cannot write the file");
}

// tools/plot_bench.py beside the sources, run with Debian's python3 (which has matplotlib).
void plot(const std::string& csv, const std::string& png) {
  const char* tools = std::getenv("ATRIUM_TOOLS_DIR");
  const std::string script = std::string(tools && *tools ? tools : ATRIUM_TOOLS_DIR) + "/plot_bench.py";
  const std::string python = std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  auto quote = [](const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
  };
  const int status = std::system((python + " " + quote(script) + " " + quote(csv) + " " + quote(png)).c_str());
  if (status != 0) throw std::runtime_error("plotting with " + script + " failed (is python3-matplotlib installed?)");
}

int run_bench_command(const CliOptions& options) {
  const auto context = gfx::HeadlessContext::create();
  BenchOptions bench = options.bench;
  bench.light_radius = options.light_radius;
  bench.scene = options.scene;
  bench.size = options.size;
  bench.shading = options.shading;
  bench.technique_options = options.technique_options;
  bench.camera = options.camera;
  bench.frustum_culling = options.frustum_culling;
  for (const std::string& mode : bench.modes) require_known_mode(mode);
  ProgressBar bar("bench");
  const BenchResult result = run_bench(bench, [&](std::size_t done, std::size_t total) { bar.update("runs", done, total); });
  const std::string md = bench_markdown(result);
  std::fputs(md.c_str(), stdout);
  if (!options.md.empty()) write_text(options.md, md);
  std::string csv_path = options.csv;
  if (!options.plot.empty() && csv_path.empty()) csv_path = options.plot + ".csv";
  if (!csv_path.empty()) write_text(csv_path, bench_csv(result));
  if (!options.plot.empty()) {
    plot(csv_path, options.plot);
    if (options.csv.empty()) std::filesystem::remove(csv_path);
  }
  return kExitOk;
}

int run_command(const CliOptions& options) {
  switch (options.command) {
    case Command::Help: std::fputs(help_text().c_str(), stdout); return kExitOk;
    case Command::Render: return run_render(options);
    case Command::Info: return run_info(options);
    case Command::Compare: return run_compare(options);
    case Command::Bench: return run_bench_command(options);
    case Command::Window: return run_window(options);
  }
  return kExitUsage;
}

int run_cli(int argc, char** argv) {
  std::vector<std::string_view> args(argv + 1, argv + argc);
  auto fail = [](const std::exception& e, int code) {
    std::fprintf(stderr, "atrium: %s\n", e.what());
    return code;
  };
  try {
    return run_command(parse_cli(args));
  } catch (const UsageError& e) {
    return fail(e, kExitUsage);
  } catch (const InputError& e) {
    return fail(e, kExitUsage);
  } catch (const assets::ImageError& e) {
    return fail(e, kExitUsage);
  } catch (const gfx::ShaderError& e) {
    std::fprintf(stderr, "atrium: shader error:\n%s\n", e.what());
    return kExitRuntimeFailure;
  } catch (const std::exception& e) {
    return fail(e, kExitRuntimeFailure);
  }
}

}  // namespace atrium
