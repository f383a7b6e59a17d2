#include "app/bench.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <map>
#include <sstream>

#include "app/world.hpp"
#include "base/format.hpp"
#include "components/frame_resources.hpp"
#include "components/light.hpp"
#include "gfx/gl.hpp"
#include "gfx/gpu_waits.hpp"
#include "gfx/limits.hpp"
#include "render/lighting/light_falloff.hpp"
#include "render/lighting/light_index_list.hpp"
#include "render/techniques/technique.hpp"
#include "systems/light_animation.hpp"

namespace atrium {
namespace {

// A mode is skipped at a light count where its frame, grown linearly from a
// smaller count, would take this many times the frame limit.
constexpr double kEstimateFactor = 4.0;
constexpr double kFirstFrameFactor = 10.0;

// NaN (a refused row, an uncountable value) prints as "-".
std::string fixed(double value, int decimals) {
  if (std::isnan(value)) return "-";
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(decimals);
  out << value;
  return out.str();
}

// A row with no times (refused or skipped): NaN prints as "-" and is left
// out of the medians.
void mark_unmeasured(BenchRow& row) {
  row.median_ms = row.p5_ms = row.p95_ms = row.gpu_ms = row.evaluated_per_pixel = std::numeric_limits<double>::quiet_NaN();
}

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const double position = p * static_cast<double>(values.size() - 1);
  const auto low = static_cast<std::size_t>(std::floor(position));
  const auto high = std::min(low + 1, values.size() - 1);
  return values[low] + (values[high] - values[low]) * (position - static_cast<double>(low));
}

// --light-radius and --constant-density: every light gets the same radius
// (WorldOptions::light_radius); with constant density it shrinks as lights grow.
std::optional<float> bench_radius(const BenchOptions& options, std::uint32_t lights) {
  if (!options.light_radius && !options.constant_density) return std::nullopt;
  float radius = options.light_radius.value_or(4.0f);
  if (options.constant_density) radius *= std::cbrt(1024.0f / static_cast<float>(std::max(lights, 1u)));
  return radius;
}

// Light evaluations per pixel that `mode` performs, from the heatmap counters;
// NaN where the driver refuses the mode at this light count.
double count_evaluations(World& world, const std::string& mode) {
  auto& settings = world.registry().resource<RendererSettings>();
  const std::string previous = world.mode();
  world.set_mode(mode);
  settings.debug_view = "heatmap";
  double count = std::numeric_limits<double>::quiet_NaN();
  try {
    world.frame(0.0);
    world.renderer().settle();  // the average comes back a frame late; this frame is not measured
    count = world.renderer().stats().light_evaluations_per_pixel;
  } catch (const gfx::ResourceLimitError&) {
  }
  settings.debug_view.clear();
  world.set_mode(previous);
  return count;
}

// Lights per pixel whose radius covers the pixel: what deferred-radius
// evaluates, which tests every light at every pixel. Past kMaxReachingTests
// such tests (a million lights at 1080p make 2e12, minutes of GPU time in one
// pass) it is not counted: NaN, an empty column.
constexpr double kMaxReachingTests = 3e11;
double count_reaching(World& world) {
  const glm::ivec2 size = world.registry().resource<Viewport>().size;
  if (static_cast<double>(world.light_count()) * size.x * size.y > kMaxReachingTests) return std::numeric_limits<double>::quiet_NaN();
  return count_evaluations(world, "deferred-radius");
}

// With the light animation running (the window's, bench --moving-lights),
// every mode is measured over the same light positions, and so are the lights
// reaching each pixel: before each, the animation's clock goes back to where
// the bench found it. Lights are placed from the clock, not moved by steps,
// so going back places them again.
class LightClock {
 public:
  explicit LightClock(World& world)
      : settings_(world.registry().try_resource<LightAnimationSettings>()), start_(settings_ ? settings_->time : 0.0) {}
  void rewind() const {
    if (settings_) settings_->time = start_;
  }

 private:
  LightAnimationSettings* settings_;
  double start_;
};

// Frame and pass times of `mode` from the world's current camera. A frame
// slower than `frame_limit_ms` ends the run after it (the row keeps that one
// frame), so one slow mode cannot hold the whole sweep. The first frame gets
// kFirstFrameFactor times the limit: it compiles the mode's programs and may
// draw every shadow map.
BenchRow measure_mode(World& world, const std::string& mode, int frames, int warmup, double reaching, double frame_limit_ms) {
  world.set_mode(mode);
  BenchRow row;
  row.mode = mode;
  row.z_slicing = world.registry().resource<RendererSettings>().technique_options.z_slicing;
  row.shadows = world.registry().resource<RendererSettings>().shadows;
  row.stage_asked = world.registry().resource<RendererSettings>().technique_options.lighting_stage;
  row.lights = world.light_count();
  row.view = world.view();
  row.view_name = world.scene().views[static_cast<std::size_t>(world.view() - 1)].name;
  row.reaching_per_pixel = reaching;
  std::vector<double> frame_ms, gpu_ms;
  std::map<std::string, std::vector<double>> pass_ms, pass_cpu_ms;
  std::vector<std::string> pass_order;
  // Per pass, its steps' names in order and their times (keyed by pass, then step).
  std::map<std::string, std::vector<std::string>> step_order;
  std::map<std::pair<std::string, std::string>, std::vector<double>> step_ms;
  std::map<std::string, std::vector<double>> system_ms;
  std::vector<std::string> system_order;
  auto slices_depth = [&] {
    const lighting::LightBins* bins = world.renderer().graph().published<lighting::LightBins>();
    return bins && bins->binning == lighting::LightBins::Binning::Clusters;
  };
  bool over_limit = false;
  for (int f = 0; f < warmup + frames && !over_limit; ++f) {
    gfx::finish();
    const auto start = std::chrono::steady_clock::now();
    try {
      world.frame(1.0 / 60.0);
    } catch (const gfx::ResourceLimitError& e) {
      row.refused = e.what();
      row.sliced = slices_depth();
      mark_unmeasured(row);
      return row;
    }
    gfx::finish();
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    over_limit = ms > (f == 0 ? kFirstFrameFactor : 1.0) * frame_limit_ms;
    if (f < warmup && !over_limit) continue;
    if (over_limit) {
      row.stopped = "one frame took " + fixed(ms, 0) + " ms, over the " + fixed(frame_limit_ms, 0) + " ms limit";
      // The GPU is idle after the finish: its pass times are there to take, and they say where the frame went.
      world.renderer().timer().wait_for_latest();
    }
    frame_ms.push_back(ms);
    row.gpu_waits = std::max(row.gpu_waits, world.renderer().stats().gpu_waits);
    double frame_gpu_ms = 0.0;
    for (const gfx::PassTime& pass : world.renderer().timer().latest()) {
      if (!pass_ms.contains(pass.name)) pass_order.push_back(pass.name);
      pass_ms[pass.name].push_back(pass.milliseconds);
      pass_cpu_ms[pass.name].push_back(pass.cpu_milliseconds);
      frame_gpu_ms += pass.milliseconds;
      for (const gfx::StepTime& step : pass.steps) {
        std::vector<double>& times = step_ms[{pass.name, step.name}];
        if (times.empty()) step_order[pass.name].push_back(step.name);
        times.push_back(step.milliseconds);
      }
    }
    gpu_ms.push_back(frame_gpu_ms);
    for (const ecs::SystemTime& system : world.scheduler().last_frame_times()) {
      if (!system_ms.contains(system.name)) system_order.push_back(system.name);
      system_ms[system.name].push_back(system.milliseconds);
    }
  }
  if (!over_limit && !frame_ms.empty()) {
    gfx::finish();
    const auto start = std::chrono::steady_clock::now();
    double paced_ms = 0.0;
    for (int f = 0; f < frames; ++f) {
      world.frame(1.0 / 60.0);
      paced_ms += world.renderer().stats().paced_ms;
    }
    gfx::finish();
    row.pipelined_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() / frames;
    row.paced_ms = paced_ms / frames;
  }
  row.sliced = slices_depth();
  if (const lighting::LightBins* bins = world.renderer().graph().published<lighting::LightBins>()) {
    const render::FrameStats& stats = world.renderer().stats();
    row.light_lists = lighting::describe(*bins) + ", " + std::string(light_assignment_label(stats.light_assignment)) + " at density " +
                      fixed(stats.light_list_density, 4);
  }
  row.median_ms = percentile(frame_ms, 0.5);
  row.p5_ms = percentile(frame_ms, 0.05);
  row.p95_ms = percentile(frame_ms, 0.95);
  row.gpu_ms = percentile(gpu_ms, 0.5);
  // The camera holds still: every measured frame submits the same draws.
  row.lighting_stage = world.renderer().stats().lighting_stage;
  row.technique_variant = world.renderer().stats().technique_variant;
  row.triangles_drawn = world.renderer().stats().triangles_drawn;
  row.triangles_occluded = world.renderer().stats().triangles_occluded;
  row.draw_calls = world.renderer().stats().draw_calls;
  for (const std::string& name : pass_order) {
    row.pass_medians.push_back({name, percentile(pass_ms[name], 0.5), 0, percentile(pass_cpu_ms[name], 0.5), {}});
    for (const std::string& step : step_order[name]) {
      const std::vector<double>& times = step_ms[{name, step}];
      row.pass_medians.back().steps.push_back({step, percentile(times, 0.5), times.size(), pass_ms[name].size()});
    }
  }
  for (const std::string& name : system_order) row.system_medians.push_back({name, percentile(system_ms[name], 0.5)});
  // Counting costs one more frame: not for a mode already over the limit.
  row.evaluated_per_pixel = over_limit ? std::numeric_limits<double>::quiet_NaN() : count_evaluations(world, mode);
  return row;
}

// Why `mode` is not measured at `lights` after the rows measured so far (empty:
// measure it): a frame at a smaller count passed the limit, or would at this
// count if its time grew with the lights (the linear cost of forward shading).
std::string skip_reason(const std::vector<BenchRow>& rows, const std::string& mode, LightingStage stage, std::uint32_t lights,
                        int shadows, double frame_limit_ms) {
  for (auto row = rows.rbegin(); row != rows.rend(); ++row) {
    if (row->mode != mode || row->stage_asked != stage || row->shadows != shadows || row->lights >= lights || !row->skipped.empty()) continue;
    if (!row->refused.empty()) return "refused at " + with_commas(row->lights) + " lights";
    const double estimate = row->median_ms * static_cast<double>(lights) / std::max(1.0, static_cast<double>(row->lights));
    if (row->median_ms > frame_limit_ms) {
      return "a frame took " + fixed(row->median_ms, 0) + " ms at " + with_commas(row->lights) + " lights, over the " + fixed(frame_limit_ms, 0) +
             " ms limit";
    }
    if (estimate > kEstimateFactor * frame_limit_ms) {
      return fixed(row->median_ms, 0) + " ms at " + with_commas(row->lights) + " lights would be about " + fixed(estimate, 0) +
             " ms here, over " + fixed(kEstimateFactor, 0) + "x the " + fixed(frame_limit_ms, 0) + " ms limit";
    }
    return {};
  }
  return {};
}

void describe_renderer(BenchResult& result, World& world) {
  if (!result.renderer.empty()) return;
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  result.renderer = renderer ? renderer : "?";
  result.timing_method = world.renderer().timer().method_name();
}

}  // namespace

BenchResult bench_current_view(World& world, int frames, int warmup) {
  BenchResult result;
  result.options.scene = world.scene().name;
  result.options.light_counts = {world.light_count()};
  result.options.views = {world.view()};
  result.options.size = world.registry().resource<Viewport>().size;
  result.options.frames = frames;
  result.options.warmup = warmup;
  const std::string previous = world.mode();
  const LightClock clock(world);
  const double reaching = count_reaching(world);
  for (const std::string& mode : world.modes()) {
    clock.rewind();
    result.rows.push_back(measure_mode(world, mode, frames, warmup, reaching, BenchOptions{}.frame_limit_ms));
    result.rows.back().view_name = "current camera";
  }
  describe_renderer(result, world);
  world.set_mode(previous);
  return result;
}

// Every pair of a shadowed-light count and a lighting stage, counts outermost.
std::vector<std::pair<int, LightingStage>> sweep(const std::vector<int>& shadow_counts,
                                                           const std::vector<LightingStage>& stages) {
  std::vector<std::pair<int, LightingStage>> pairs;
  for (const int shadows : shadow_counts) {
    for (const LightingStage stage : stages) pairs.emplace_back(shadows, stage);
  }
  return pairs;
}

BenchResult run_bench(const BenchOptions& options, const BenchProgress& progress) {
  BenchResult result;
  result.options = options;
  const std::vector<std::string> modes = options.modes.empty() ? techniques::mode_names() : options.modes;
  const std::vector<ZSlicing> slicings =
      options.z_slicings.empty() ? std::vector{options.technique_options.z_slicing} : options.z_slicings;
  const std::vector<int> shadow_counts = options.shadow_counts.empty() ? std::vector{0} : options.shadow_counts;
  const std::vector<LightingStage> stages =
      options.lighting_stages.empty() ? std::vector{options.technique_options.lighting_stage} : options.lighting_stages;
  std::vector<std::uint32_t> light_counts = options.light_counts;
  std::sort(light_counts.begin(), light_counts.end());  // skipping learns from the smaller counts
  WorldOptions world_options;
  world_options.scene = options.scene;
  world_options.lights = light_counts.empty() ? 0 : light_counts.front();
  world_options.mode = "forward";
  world_options.size = options.size;
  world_options.shading = options.shading;
  world_options.technique_options = options.technique_options;
  world_options.light_radius = bench_radius(options, world_options.lights.value_or(0));
  world_options.camera = options.camera;
  world_options.frustum_culling = options.frustum_culling;
  world_options.occlusion_culling = options.occlusion_culling;
  world_options.culling_device = options.culling_device;
  world_options.system_options = options.system_options;
  // One world for the sweep: the scene loads once, and each count replaces
  // the lights as a world made with that count would have them.
  World world(world_options);
  if (options.moving_lights) register_light_animation(world.scheduler(), world.registry());
  const LightClock clock(world);
  std::vector<int> views = options.views;
  if (views.empty()) {
    for (int v = 1; v <= static_cast<int>(world.scene().views.size()); ++v) views.push_back(v);
  }
  const std::size_t total = light_counts.size() * modes.size() * slicings.size() * stages.size() * shadow_counts.size() * views.size();
  std::size_t done = 0;
  auto& settings = world.registry().resource<RendererSettings>();
  settings.redraw_shadows = options.shadow_redraw;
  world.renderer().timer().time_steps(options.pass_steps);
  for (const std::uint32_t lights : light_counts) {
    if (lights != world.light_count()) world.set_light_count(lights);
    if (options.light_radius || options.constant_density) world.set_light_radius(bench_radius(options, lights));
    // The built-in scene's first lights are its lamps', which stay put: a
    // small count can have no moving light where a larger one has many.
    if (options.moving_lights && world.registry().count<LightAnimation>() == 0) {
      std::fprintf(stderr, "note: --moving-lights: at %u lights %s has no animated lights (a scene file's or model's generated lights move)\n",
                   lights, world.scene().name.c_str());
    }
    for (const int view : views) {
      world.set_view(view);
      clock.rewind();
      const double reaching = count_reaching(world);
      for (const auto& [shadows, stage] : sweep(shadow_counts, stages)) {
        settings.shadows = shadows;
        settings.technique_options.lighting_stage = stage;
        // Modes that do not slice depth are measured once, with the first slicing.
        std::vector<std::string> to_measure = modes;
        for (const ZSlicing slicing : slicings) {
          settings.technique_options.z_slicing = slicing;
          for (const std::string& mode : modes) {
            if (std::find(to_measure.begin(), to_measure.end(), mode) == to_measure.end()) {
              done += 1;
              continue;
            }
            BenchRow row;
            const std::string skipped = skip_reason(result.rows, mode, stage, lights, shadows, options.frame_limit_ms);
            if (skipped.empty()) {
              clock.rewind();
              row = measure_mode(world, mode, options.frames, options.warmup, reaching, options.frame_limit_ms);
            } else {
              row.mode = mode;
              row.lights = lights;
              row.view = view;
              row.view_name = world.scene().views[static_cast<std::size_t>(view - 1)].name;
              row.shadows = shadows;
              row.z_slicing = slicing;
              row.stage_asked = stage;
              row.skipped = skipped;
              mark_unmeasured(row);
              row.reaching_per_pixel = reaching;
            }
            if (!row.sliced) std::erase(to_measure, mode);
            result.rows.push_back(std::move(row));
            if (progress) progress(++done, total, result.rows.back());
          }
        }
      }
    }
  }
  describe_renderer(result, world);
  return result;
}

namespace {

// The markdown table lists the systems that took at least this long (the CSV all of them).
constexpr double kListedSystemMs = 0.05;

// A row's column in the tables: its mode, with the depth slicing when the
// bench compares several ("clustered-deferred/uniform").
std::string label(const BenchResult& result, const BenchRow& row) {
  std::string name = row.mode;
  if (result.options.z_slicings.size() >= 2 && row.sliced) {
    name += "/" + std::string(kZSlicingNames[static_cast<std::size_t>(row.z_slicing)]);
  }
  if (result.options.lighting_stages.size() >= 2) name += "/" + std::string(kLightingStageNames[static_cast<std::size_t>(row.stage_asked)]);
  if (result.options.shadow_counts.size() >= 2) name += " " + std::to_string(row.shadows) + " shadowed";
  return name;
}

// Median over views of each (lights, label) frame time; NaN where every view was refused or skipped.
std::map<std::pair<std::uint32_t, std::string>, double> median_over_views(const BenchResult& result) {
  std::map<std::pair<std::uint32_t, std::string>, std::vector<double>> times;
  for (const BenchRow& row : result.rows) {
    auto& values = times[{row.lights, label(result, row)}];
    if (!std::isnan(row.median_ms)) values.push_back(row.median_ms);
  }
  std::map<std::pair<std::uint32_t, std::string>, double> medians;
  for (const auto& [key, values] : times) medians[key] = values.empty() ? std::numeric_limits<double>::quiet_NaN() : percentile(values, 0.5);
  return medians;
}

std::vector<std::string> modes_in_order(const BenchResult& result) {
  std::vector<std::string> modes;
  for (const BenchRow& row : result.rows) {
    const std::string name = label(result, row);
    if (std::find(modes.begin(), modes.end(), name) == modes.end()) modes.push_back(name);
  }
  return modes;
}

}  // namespace

std::string bench_markdown(const BenchResult& result) {
  const auto& o = result.options;
  const auto medians = median_over_views(result);
  const auto modes = modes_in_order(result);
  std::ostringstream md;
  md << "Scene `" << o.scene << "`, " << o.size.x << "x" << o.size.y << ", " << o.frames << " frames after " << o.warmup
     << " warm-up, shading " << o.shading;
  if (o.light_radius) md << ", light radius " << fixed(*o.light_radius, 2) << " m";
  if (o.constant_density) md << ", constant density";
  if (o.technique_options.msaa > 1) md << ", MSAA " << o.technique_options.msaa << "x";
  if (o.shadow_counts.size() == 1 && o.shadow_counts[0] > 0) md << ", shadow maps for " << o.shadow_counts[0] << " lights";
  if (!o.shadow_counts.empty() && o.shadow_redraw) md << " (every map drawn every frame)";
  if (o.moving_lights) md << ", the scene's animated lights moving";
  if (o.technique_options.compute_free) md << ", the compute-free tier (--no-compute, no occlusion culling)";
  else if (!o.occlusion_culling) {
    md << ", no occlusion culling";
  } else if (o.culling_device != CullingDevice::Automatic) {
    md << ", occlusion culling on the " << (o.culling_device == CullingDevice::Gpu ? "GPU" : "CPU");
  }
  md << ".\nRenderer: " << result.renderer << "; pass timing: " << result.timing_method
     << ". Frames per second from the median frame time (median over views).\n\n";
  md << "| lights |";
  for (const auto& mode : modes) md << " " << mode << " |";
  md << "\n|---:|";
  for (std::size_t i = 0; i < modes.size(); ++i) md << "---:|";
  md << "\n";
  std::vector<std::uint32_t> counts;
  for (const BenchRow& row : result.rows) {
    if (std::find(counts.begin(), counts.end(), row.lights) == counts.end()) counts.push_back(row.lights);
  }
  for (const std::uint32_t lights : counts) {
    md << "| " << lights << " |";
    for (const auto& mode : modes) {
      const double ms = medians.at({lights, mode});
      md << " " << (std::isnan(ms) ? std::string("-") : fixed(1000.0 / ms, 1) + " fps") << " |";
    }
    md << "\n";
  }
  if (std::find(modes.begin(), modes.end(), "forward") != modes.end()) {
    md << "\nSpeed-up over forward (frame time of forward / frame time of the mode):\n\n| lights |";
    for (const auto& mode : modes) md << " " << mode << " |";
    md << "\n|---:|";
    for (std::size_t i = 0; i < modes.size(); ++i) md << "---:|";
    md << "\n";
    for (const std::uint32_t lights : counts) {
      md << "| " << lights << " |";
      for (const auto& mode : modes) {
        const double ratio = medians.at({lights, "forward"}) / medians.at({lights, mode});
        md << " " << (std::isnan(ratio) ? std::string("-") : fixed(ratio, 2) + "x") << " |";
      }
      md << "\n";
    }
  }
  md << "\nPer mode, light count and view (times in ms; evaluated and reaching are lights per pixel, averaged over the image; "
        "passes' sum is the frame's passes as the pass timing measured them, GPU time with timer queries; GPU waits are calls "
        "in one frame that could wait for the GPU; pipelined is the frame with frames submitted back to back, one frame's CPU work "
        "overlapping the GPU's of the one before, as in a window; paced is the part of a pipelined frame the CPU waited "
        "before it for the GPU to finish the frame two before (near pipelined: GPU-bound; near 0: the CPU sets the pace); "
        "systems are the CPU time of those over 0.05 ms, the renderer's including its passes' submission; in brackets after a pass, "
        "with --pass-steps, the steps it names, a step that ran in some of the frames only with its median over those):\n\n"
        "| mode | lights | view | median | p5 | p95 | fps | pipelined | paced | passes (median) | evaluated | reaching | efficiency | triangles drawn | draws | passes' sum | GPU waits | light lists | systems (CPU, median) |\n"
        "|---|---:|---|---:|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---|---|\n";
  for (const BenchRow& row : result.rows) {
    std::string passes;
    for (const auto& pass : row.pass_medians) {
      passes += (passes.empty() ? "" : ", ") + pass.name + " " + fixed(pass.milliseconds, 2);
      std::string steps;
      for (const gfx::StepTime& step : pass.steps) {
        steps += (steps.empty() ? "" : ", ") + step.name + " " + fixed(step.milliseconds, 2);
        if (step.frames < step.pass_frames) steps += " (" + std::to_string(step.frames) + " of " + std::to_string(step.pass_frames) + " frames)";
      }
      if (!steps.empty()) passes += " [" + steps + "]";
    }
    if (!row.refused.empty()) passes = "refused: " + row.refused;
    if (!row.skipped.empty()) passes = "skipped: " + row.skipped;
    if (!row.stopped.empty()) passes = "stopped: " + row.stopped + "; " + passes;
    std::string systems;
    for (const ecs::SystemTime& system : row.system_medians) {
      if (system.milliseconds < kListedSystemMs) continue;
      const std::string_view name = std::string_view(system.name).substr(system.name.find('/') + 1);
      systems += (systems.empty() ? "" : ", ") + std::string(name) + " " + fixed(system.milliseconds, 2);
    }
    md << "| " << label(result, row) << " | " << row.lights << " | " << row.view << " " << row.view_name << " | " << fixed(row.median_ms, 2)
       << " | " << fixed(row.p5_ms, 2) << " | " << fixed(row.p95_ms, 2) << " | " << fixed(row.fps(), 1) << " | "
       << fixed(row.pipelined_ms, 2) << " | " << fixed(row.paced_ms, 2) << " | " << passes
       << " | " << fixed(row.evaluated_per_pixel, 2) << " | " << fixed(row.reaching_per_pixel, 2) << " | "
       << fixed(row.efficiency(), 3) << " | " << row.triangles_drawn << " | " << row.draw_calls << " | " << fixed(row.gpu_ms, 2) << " | "
       << (std::isnan(row.median_ms) ? std::string("-") : std::to_string(row.gpu_waits)) << " | " << row.light_lists << " | " << systems << " |\n";
  }
  return md.str();
}

std::string bench_csv(const BenchResult& result) {
  std::ostringstream csv;
  csv << "mode,lights,view,view_name,width,height,frames,median_ms,p5_ms,p95_ms,fps,evaluated_per_pixel,"
         "reaching_per_pixel,efficiency,passes,timing_method,renderer,refused,triangles_drawn,draw_calls,cpu_passes,z_slicing,shadows,"
         "triangles_occluded,gpu_ms,gpu_waits,skipped,lighting_stage,light_lists,cpu_systems,pipelined_ms,technique_variant,pass_steps,paced_ms\n";
  for (const BenchRow& row : result.rows) {
    std::string passes;
    std::string cpu_passes;
    std::string pass_steps;  // "pass/step=ms;...", "=ms@N/M" for a step that ran in N of the pass's M frames
    for (const auto& pass : row.pass_medians) {
      passes += (passes.empty() ? "" : ";") + pass.name + "=" + fixed(pass.milliseconds, 4);
      cpu_passes += (cpu_passes.empty() ? "" : ";") + pass.name + "=" + fixed(pass.cpu_milliseconds, 4);
      for (const gfx::StepTime& step : pass.steps) {
        pass_steps += (pass_steps.empty() ? "" : ";") + pass.name + "/" + step.name + "=" + fixed(step.milliseconds, 4);
        if (step.frames < step.pass_frames) pass_steps += "@" + std::to_string(step.frames) + "/" + std::to_string(step.pass_frames);
      }
    }
    std::string cpu_systems;
    for (const ecs::SystemTime& system : row.system_medians) {
      cpu_systems += (cpu_systems.empty() ? "" : ";") + system.name + "=" + fixed(system.milliseconds, 4);
    }
    csv << row.mode << "," << row.lights << "," << row.view << "," << row.view_name << "," << result.options.size.x << ","
        << result.options.size.y << "," << result.options.frames << "," << fixed(row.median_ms, 4) << "," << fixed(row.p5_ms, 4)
        << "," << fixed(row.p95_ms, 4) << "," << fixed(row.fps(), 3) << "," << fixed(row.evaluated_per_pixel, 4) << ","
        << fixed(row.reaching_per_pixel, 4) << "," << fixed(row.efficiency(), 4) << ",\"" << passes << "\",\""
        << result.timing_method << "\",\"" << result.renderer << "\",\"" << row.refused << "\"," << row.triangles_drawn << ","
        << row.draw_calls << ",\"" << cpu_passes << "\","
        << (row.sliced ? kZSlicingNames[static_cast<std::size_t>(row.z_slicing)] : std::string_view()) << ","
        << row.shadows << "," << row.triangles_occluded << "," << fixed(row.gpu_ms, 4) << ","
        << (std::isnan(row.median_ms) ? std::string() : std::to_string(row.gpu_waits)) << ",\"" << (row.skipped.empty() ? row.stopped : row.skipped)
        << "\","
        << (std::isnan(row.median_ms) ? std::string_view() : kLightingStageNames[static_cast<std::size_t>(row.lighting_stage)])
        << ",\"" << row.light_lists << "\",\"" << cpu_systems << "\"," << fixed(row.pipelined_ms, 4) << ",\"" << row.technique_variant
        << "\",\"" << pass_steps << "\"," << fixed(row.paced_ms, 4) << "\n";
  }
  return csv.str();
}

}  // namespace atrium
