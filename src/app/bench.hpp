// `atrium bench`: frame times and per-pass times over modes, light counts and
// views, with the light evaluations each mode performs per pixel against the
// ones that actually reach the pixel, written as a reference-shaped markdown
// table, CSV and a plot.
#pragma once

#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "assets/scene.hpp"
#include "ecs/scheduler.hpp"
#include "gfx/pass_timer.hpp"
#include "components/frame_resources.hpp"
#include "components/technique_options.hpp"

namespace atrium {

struct BenchOptions {
  std::string scene = "atrium";
  std::vector<std::string> modes;            // empty: every mode in the table
  std::vector<std::uint32_t> light_counts{10, 50, 110, 1024};
  std::vector<int> views;                    // empty: every stored view
  std::optional<assets::NamedView> camera;   // replaces the scene's views (--camera)
  glm::ivec2 size{320, 180};
  int frames = 30;
  int warmup = 5;
  std::optional<float> light_radius;         // every light gets this radius
  bool constant_density = false;             // radii shrink as cbrt(1024 / lights)
  std::string shading = "pbr";
  TechniqueOptions technique_options;
  // --z-slicing LIST: every mode is measured with each (empty: technique_options').
  std::vector<ZSlicing> z_slicings;
  // --lighting-stage LIST: every mode is measured in each stage (empty: technique_options').
  std::vector<LightingStage> lighting_stages;
  bool frustum_culling = true;               // --no-culling
  bool occlusion_culling = true;             // --no-occlusion-culling
  CullingDevice culling_device = CullingDevice::Automatic;  // --culling
  // Settings of optional systems (components/system_options.hpp): every row has them.
  std::map<std::string, double> system_options;
  // --shadows LIST: every mode is measured with each shadowed-light count (empty: none).
  std::vector<int> shadow_counts;
  bool shadow_redraw = false;                // --shadow-redraw: every map drawn every frame
  bool pass_steps = false;                   // --pass-steps: the steps each pass names, timed apart
  bool moving_lights = false;                // --moving-lights: the light animation runs, 1/60 s a frame, as in the window
  // --frame-limit: a run stops after a frame slower than this, and a mode is
  // skipped at the larger light counts that would pass it (BenchRow::skipped).
  double frame_limit_ms = 1000.0;
};

struct BenchRow {
  std::string mode;
  // The depth slicing the row ran with, and whether the mode bins lights by
  // depth slices at all (a clustered mode): only those are measured per slicing.
  ZSlicing z_slicing = ZSlicing::Log;
  bool sliced = false;
  // How the mode's light lists cut the frame and were built ("60x34x32
  // clusters, gather"; empty for modes without lists): --cluster-grid and
  // --light-assignment as they ran.
  std::string light_lists;
  std::string technique_variant;  // FrameStats::technique_variant
  int shadows = 0;  // lights with shadow maps (--shadows)
  // The stage asked for (a sweep's) and the one the full-screen passes ran in.
  LightingStage stage_asked = LightingStage::Automatic;
  LightingStage lighting_stage = LightingStage::Fragment;
  std::uint32_t lights = 0;
  int view = 1;
  std::string view_name;
  double median_ms = 0, p5_ms = 0, p95_ms = 0;
  double gpu_ms = 0;  // median over frames of the passes' summed times (GPU time with timer queries)
  // The same frames submitted back to back, the total over their count: the
  // frame as a window sees it, one frame's CPU work overlapping the GPU's work
  // of the one before (median_ms adds the two: glFinish before and after each).
  double pipelined_ms = std::numeric_limits<double>::quiet_NaN();
  // Of pipelined_ms, the time the CPU waited before a frame for the GPU to
  // finish the one two before it (FramePacer::waited_ms, mean per frame): near
  // pipelined_ms the loop was GPU-bound, near 0 the CPU set the pace.
  double paced_ms = std::numeric_limits<double>::quiet_NaN();
  // The most calls that could wait for the GPU in one measured frame
  // (FrameStats::gpu_waits): 0 in a frame that never stalls the GPU.
  std::uint32_t gpu_waits = 0;
  std::vector<gfx::PassTime> pass_medians;  // GPU and CPU (submission) medians per pass
  // Each system's CPU time, median over the measured frames ("Render/light_buffer"):
  // where the frame goes besides its passes. The renderer's includes its passes' submission.
  std::vector<ecs::SystemTime> system_medians;
  std::size_t triangles_drawn = 0;  // per geometry pass, after frustum and occlusion culling
  std::size_t triangles_occluded = 0;  // in view, but left out as hidden (occlusion culling)
  std::size_t draw_calls = 0;       // per geometry pass
  double evaluated_per_pixel = 0;  // light evaluations the mode performed
  double reaching_per_pixel = 0;   // lights whose radius covers the pixel; NaN where not countable
  // Why the driver refused this mode at this light count (gfx::ResourceLimitError),
  // or empty; a refused row has no times.
  std::string refused;
  // Why this run was not measured (a smaller light count passed the frame
  // limit), or empty; a skipped row has no times.
  std::string skipped;
  // Set when the run stopped after one frame over the limit (its times are that frame's).
  std::string stopped;
  [[nodiscard]] double fps() const { return median_ms > 0 ? 1000.0 / median_ms : std::numeric_limits<double>::quiet_NaN(); }
  // 1.0: the mode evaluates only lights that reach; lower: wasted evaluations.
  // NaN where either count is unknown (a refused mode).
  [[nodiscard]] double efficiency() const {
    if (std::isnan(evaluated_per_pixel) || std::isnan(reaching_per_pixel)) return std::numeric_limits<double>::quiet_NaN();
    return evaluated_per_pixel > 0 ? reaching_per_pixel / evaluated_per_pixel : 1.0;
  }
};

struct BenchResult {
  std::vector<BenchRow> rows;
  std::string renderer;
  std::string timing_method;
  BenchOptions options;
};

// Called after each run with the runs done, the runs in all and the row just added.
using BenchProgress = std::function<void(std::size_t done, std::size_t total, const BenchRow& row)>;

// Needs a current GL context. Reports each run to `progress` (may be empty).
[[nodiscard]] BenchResult run_bench(const BenchOptions& options, const BenchProgress& progress = {});

class World;
// Every mode from the world's current camera, at its light count and size
// (`b` in the window); the world's mode is restored.
[[nodiscard]] BenchResult bench_current_view(World& world, int frames, int warmup);

[[nodiscard]] std::string bench_markdown(const BenchResult& result);
[[nodiscard]] std::string bench_csv(const BenchResult& result);

}  // namespace atrium
