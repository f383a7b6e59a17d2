#include "app/cli.hpp"

#include <cstdlib>
#include <fstream>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <vector>

#include "app/info.hpp"
#include "app/probe.hpp"
#include "app/world.hpp"
#include "components/frame_resources.hpp"
#include "assets/image.hpp"
#include "assets/load_budget.hpp"
#include "gfx/context.hpp"
#include "gfx/limits.hpp"
#include "gfx/shader_program.hpp"
#include "render/debug/debug_views.hpp"
#include "render/lighting/lighting_pass.hpp"
#include "render/techniques/technique.hpp"

namespace atrium {

namespace {

// A file a command writes once its work is done: its folder must exist
// before the work starts, so that a bench measuring for minutes does not fail
// at the end (exit 2).
void require_folder_of(const std::string& file) {
  const std::filesystem::path path(file);
  if (path.has_parent_path() && !std::filesystem::is_directory(path.parent_path())) {
    throw InputError(file + ": the folder " + path.parent_path().string() + " does not exist");
  }
}

// `render --debug-view list`: the views the mode's graph (with these options)
// offers, one per line with what each shows.
int list_debug_views(const CliOptions& options) {
  const auto context = gfx::HeadlessContext::create({.api = options.gl_api});
  WorldOptions listed = world_options(options);
  listed.debug_view.clear();
  listed.size = {16, 16};  // one frame makes the technique; its picture is not needed
  World world(listed);
  world.frame(0.0);
  for (const render::OfferedView& view : world.renderer().offered_views()) {
    std::printf("%-24s %s\n", view.name.c_str(), view.help.c_str());
  }
  return kExitOk;
}

int run_render(const CliOptions& options) {
  if (options.debug_view == "list") return list_debug_views(options);
  const std::filesystem::path out(options.out);
  require_folder_of(options.out);
  const auto context = gfx::HeadlessContext::create({.api = options.gl_api});
  World world(world_options(options));
  world.frame(0.0);
  require_offered_view(world, options.debug_view);
  assets::write_png(out, world.renderer().read_output());
  world.renderer().settle();  // what the GPU reports a frame late: averages, list totals, pass timings
  const render::FrameStats& stats = world.renderer().stats();
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
  const render::GraphMemory memory = world.renderer().graph().memory();
  std::printf("render targets: %s long-lived (imported into the frame graph), %s transient (%s if none shared an object)\n",
              format_bytes(static_cast<double>(memory.imported_bytes)).c_str(),
              format_bytes(static_cast<double>(memory.aliased_bytes)).c_str(),
              format_bytes(static_cast<double>(memory.transient_bytes)).c_str());
  if (stats.shadows.atlas_size > 0) {
    std::printf("shadows: %u lights shadowed, %u maps drawn, %u reused, %zu triangles in shadow passes (%dx%d atlas)\n",
                stats.shadows.lights, stats.shadows.maps_rendered, stats.shadows.maps_reused, stats.shadows.triangles,
                stats.shadows.atlas_size, stats.shadows.atlas_size);
  }
  if (!stats.technique_variant.empty()) std::printf("technique: %s\n", stats.technique_variant.c_str());
  if (stats.light_list_entries > 0) {
    std::printf("light lists: %u entries (%s, density %.4f), %u overflowed frames%s\n", stats.light_list_entries,
                std::string(light_assignment_label(stats.light_assignment)).c_str(), stats.light_list_density, stats.light_list_overflows,
                stats.light_list_overflows > 0 ? " (their lights that did not fit were shaded wherever they reach; the list grew)" : "");
  }
  return kExitOk;
}

}  // namespace

int run_info(const CliOptions& options) {
  const auto context = gfx::HeadlessContext::create({.api = options.gl_api});
  WorldOptions loaded = world_options(options);
  loaded.size = {16, 16};  // info renders nothing worth a large target
  World world(loaded);
  SceneInfo info = gather_info(world, options.scene, options.size);
  info.gl = context->info();
  if (options.memory) {
    world.set_size(options.size);
    info.memory_size = options.size;
    for (const std::string& mode : world.modes()) {
      world.set_mode(mode);
      world.frame(0.0);
      info.memory.push_back({mode, world.renderer().graph().memory(), world.renderer().graph().used_resources()});
    }
  }
  std::fputs((options.json ? format_info_json(info) : format_info_text(info)).c_str(), stdout);
  return kExitOk;
}

// Every mode at every view, in each lighting stage, against forward drawn in
// the fragment stage: PSNR and largest channel difference.
int run_compare(const CliOptions& options) {
  const std::string below = "  < " + std::to_string(static_cast<int>(kMinimumPsnr)) + " dB";
  const auto context = gfx::HeadlessContext::create({.api = options.gl_api});
  WorldOptions compared = world_options(options);
  compared.mode = "forward";
  compared.lighting_stage = LightingStage::Fragment;
  // A texel a mode leaves unwritten would keep forward's colour and pass.
  compared.poison_targets = true;
  World world(compared);
  TechniqueOptions& technique_options = world.registry().resource<RendererSettings>().technique_options;
  // By default both stages, less one this context cannot run (said once).
  std::vector<LightingStage> stages = options.lighting_stages;
  if (stages.empty()) {
    for (const LightingStage stage : {LightingStage::Fragment, LightingStage::Compute}) {
      TechniqueOptions asked = technique_options;
      asked.lighting_stage = stage;
      try {
        (void)lighting::resolve_lighting_stage(asked);
        stages.push_back(stage);
      } catch (const gfx::ResourceLimitError& e) {
        std::printf("not compared: %s\n", e.what());
      }
    }
  }
  std::printf("%-24s %-9s %-18s %10s %9s\n", "mode", "stage", "view", "PSNR", "max diff");
  bool all_close = true;
  for (int view = 1; view <= static_cast<int>(world.scene().views.size()); ++view) {
    world.set_view(view);
    world.set_mode("forward");
    technique_options.lighting_stage = LightingStage::Fragment;
    world.frame(0.0);
    const assets::Image reference = world.renderer().read_output();
    const std::string view_name = std::to_string(view) + " " + world.scene().views[static_cast<std::size_t>(view - 1)].name;
    for (const LightingStage stage : stages) {
      technique_options.lighting_stage = stage;
      for (const auto& technique : techniques::technique_table()) {
        if (technique.name == "forward" && stage == LightingStage::Fragment) continue;
        if (const std::string why = techniques::refusal(technique, technique_options); !why.empty()) {
          if (view == 1 && stage == stages.front()) std::printf("%-24s not compared: %s\n", std::string(technique.name).c_str(), why.c_str());
          continue;
        }
        world.set_mode(std::string(technique.name));
        world.frame(0.0);
        const assets::Image image = world.renderer().read_output();
        const double psnr = assets::psnr(reference, image);
        const bool close = psnr >= kMinimumPsnr;
        all_close = all_close && close;
        const std::string_view ran = lighting::lighting_stage_name(world.renderer().stats().lighting_stage);
        std::printf("%-24s %-9s %-18s %7.2f dB %9d%s\n", std::string(technique.name).c_str(), std::string(ran).c_str(), view_name.c_str(),
                    std::isinf(psnr) ? 999.99 : psnr, assets::max_channel_difference(reference, image), close ? "" : below.c_str());
      }
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
  for (const std::string* file : {&options.md, &options.csv, &options.plot}) {
    if (!file->empty()) require_folder_of(*file);
  }
  const auto context = gfx::HeadlessContext::create({.api = options.gl_api});
  BenchOptions bench = options.bench;
  bench.light_radius = options.light_radius;
  bench.scene = options.scene;
  bench.size = options.size;
  bench.shading = options.shading;
  bench.technique_options = options.technique_options;
  bench.camera = options.camera;
  bench.frustum_culling = options.frustum_culling;
  bench.occlusion_culling = options.occlusion_culling;
  bench.culling_device = options.culling_device;
  bench.lighting_stages = options.lighting_stages;
  bench.system_options = options.system_options;
  for (const std::string& mode : bench.modes) require_known_mode(mode);
  // One line per run on stderr: a long sweep (a GPU kit run) shows where it is.
  const BenchResult result = run_bench(bench, [](std::size_t done, std::size_t total, const BenchRow& row) {
    std::string outcome = row.refused.empty() ? "" : "refused";
    if (!row.skipped.empty()) outcome = "skipped: " + row.skipped;
    if (outcome.empty()) {
      char time[32];
      std::snprintf(time, sizeof time, "%.2f ms", row.median_ms);
      outcome = time + (", " + std::to_string(row.gpu_waits) + " GPU waits");
      if (!row.stopped.empty()) {
        // Where the slow frame went, should the sweep not live to write its tables.
        std::string passes;
        for (const gfx::PassTime& pass : row.pass_medians) {
          std::snprintf(time, sizeof time, " %.1f ms", pass.milliseconds);
          passes += (passes.empty() ? "" : ", ") + pass.name + time;
        }
        outcome += " (stopped: " + row.stopped + "; passes: " + passes + ")";
      }
    }
    std::fprintf(stderr, "bench %zu/%zu: %s, %u lights, view %d: %s\n", done, total, row.mode.c_str(), row.lights, row.view, outcome.c_str());
  });
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

int run_probe(const CliOptions& options) {
  const auto context = gfx::HeadlessContext::create({.api = options.gl_api});
  if (options.size.x > gfx::max_render_size().x || options.size.y > gfx::max_render_size().y) {
    throw UsageError("--size " + std::to_string(options.size.x) + "x" + std::to_string(options.size.y) + " is larger than this context renders (" +
                     std::to_string(gfx::max_render_size().x) + "x" + std::to_string(gfx::max_render_size().y) + ")");
  }
  const std::string& renderer = context->info().renderer;
  const gfx::StageProbeResult stages = gfx::run_stage_probe(options.size);
  if (options.json) {
    std::fputs(format_probe_json(stages, gfx::run_raster_probe(options.size), renderer).c_str(), stdout);
    return kExitOk;
  }
  // The SM counts out first: they are what a GPU session learns first, kept
  // even if the raster probe then fails on a driver.
  std::fputs(format_probe_text(stages, renderer).c_str(), stdout);
  std::fflush(stdout);
  std::fputs(format_raster_probe_text(gfx::run_raster_probe(options.size)).c_str(), stdout);
  return kExitOk;
}

int run_command(const CliOptions& options) {
  switch (options.command) {
    case Command::Help: std::fputs(help_text(options.help_topic).c_str(), stdout); return kExitOk;
    case Command::Version: std::fputs(version_text().c_str(), stdout); return kExitOk;
    case Command::Render: return run_render(options);
    case Command::Info: return run_info(options);
    case Command::Compare: return run_compare(options);
    case Command::Bench: return run_bench_command(options);
    case Command::Probe: return run_probe(options);
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
  } catch (const render::UnknownViewError& e) {
    return fail(e, kExitUsage);  // found by the first frame: its graph does not offer that view
  } catch (const gfx::ShaderError& e) {
    std::fprintf(stderr, "atrium: shader error:\n%s\n", e.what());
    return kExitRuntimeFailure;
  } catch (const std::exception& e) {
    return fail(e, kExitRuntimeFailure);
  }
}

}  // namespace atrium
