#include "app/probe.hpp"

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <numeric>
#include <utility>

#include <nlohmann/json.hpp>

namespace atrium {
namespace {

// printf onto the end of text; the attribute has the compiler check each
// format string against its arguments.
[[gnu::format(printf, 2, 3)]] void append(std::string& text, const char* format, ...) {
  char line[512];
  std::va_list values;
  va_start(values, format);
  std::vsnprintf(line, sizeof line, format, values);
  va_end(values);
  text += line;
}

double gflops(const gfx::StageProbeResult& r, const gfx::StageReach& reach) {
  return reach.milliseconds > 0 ? r.flops() / (reach.milliseconds * 1e6) : 0.0;
}

// The share of the census's invocations that the busiest SM ran: 1/N when N
// SMs share the work evenly.
double busiest_share(const gfx::StageReach& reach) {
  const std::uint64_t total = std::accumulate(reach.invocations.begin(), reach.invocations.end(), std::uint64_t{0});
  if (total == 0) return 0;
  return static_cast<double>(*std::max_element(reach.invocations.begin(), reach.invocations.end())) / static_cast<double>(total);
}

// Thousands of triangles a millisecond: millions a second.
double mtriangles(const gfx::RasterProbeResult& r, double milliseconds) {
  return milliseconds > 0 ? r.triangles / (milliseconds * 1e3) : 0.0;
}

std::string raster_text(const gfx::RasterProbeResult& r) {
  std::string text;
  append(text, "triangles    %u of about 2 pixels in %u layers over %dx%d (each layer passes the depth test), %s, median of %u runs\n",
         r.triangles, r.layers, r.size.x, r.size.y,
         r.identifiers ? "depth and identifier" : "depth and identifier by the raster pipeline, depth alone by compute (no 64-bit atomics)",
         r.runs);
  append(text, "raster       %.3f ms, %.0f Mtriangles/s\n", r.raster_ms, mtriangles(r, r.raster_ms));
  append(text, "compute      %.3f ms, %.0f Mtriangles/s (a triangle an invocation)\n", r.compute_ms, mtriangles(r, r.compute_ms));
  if (r.compute_ms > 0) append(text, "ratio        raster time / compute time: %.2f\n", r.raster_ms / r.compute_ms);
  append(text, "agreement    %llu of %llu covered pixels differ in depth", static_cast<unsigned long long>(r.depth_mismatches),
         static_cast<unsigned long long>(r.covered));
  if (r.identifiers) append(text, ", %llu in identifier", static_cast<unsigned long long>(r.identifier_mismatches));
  text += "\n";
  return text;
}

}  // namespace

std::string format_probe_text(const gfx::StageProbeResult& r, const gfx::RasterProbeResult& raster, const std::string& renderer) {
  std::string text;
  append(text, "gpu          %s\n", renderer.c_str());
  if (r.sm_ids) {
    append(text, "SMs          %u (GL_SM_COUNT_NV), warps of %u threads, %u warps per SM\n", r.sm_count, r.warp_size, r.warps_per_sm);
  } else {
    append(text, "SMs          not reported: the driver has no GL_NV_shader_thread_group (NVIDIA's); times only\n");
  }
  append(text, "work         %dx%d pixels, %u iterations of 8 multiply-adds (%.2f Gflop a pass), median of %u runs, %s\n", r.size.x, r.size.y,
      r.iterations, r.flops() / 1e9, r.runs, r.timing.c_str());
  for (const auto& [name, reach] : {std::pair{"compute ", &r.compute}, std::pair{"fragment", &r.fragment}}) {
    append(text, "%s     %.3f ms, %.0f Gflop/s", name, reach->milliseconds, gflops(r, *reach));
    if (r.sm_ids) {
      append(text, "; ran on %u of %u SMs, the busiest running %.1f%% of the invocations", reach->sms_reached(), r.sm_count,
          100.0 * busiest_share(*reach));
    }
    text += "\n";
  }
  if (r.compute.milliseconds > 0) append(text, "ratio        fragment time / compute time: %.2f\n", r.fragment.milliseconds / r.compute.milliseconds);
  return text + raster_text(raster);
}

std::string format_probe_json(const gfx::StageProbeResult& r, const gfx::RasterProbeResult& raster, const std::string& renderer) {
  auto stage = [&](const gfx::StageReach& reach) {
    nlohmann::json j = {{"milliseconds", reach.milliseconds}, {"gflops", gflops(r, reach)}};
    if (r.sm_ids) {
      j["sms_reached"] = reach.sms_reached();
      j["busiest_sm_share"] = busiest_share(reach);
      j["invocations_per_sm"] = reach.invocations;
    }
    return j;
  };
  nlohmann::json j = {{"gpu", renderer},
                      {"size", {r.size.x, r.size.y}},
                      {"iterations", r.iterations},
                      {"flops_per_pass", r.flops()},
                      {"runs", r.runs},
                      {"timing", r.timing},
                      {"sm_ids", r.sm_ids},
                      {"sm_count", r.sm_ids ? nlohmann::json(r.sm_count) : nlohmann::json(nullptr)},
                      {"compute", stage(r.compute)},
                      {"fragment", stage(r.fragment)},
                      {"fragment_over_compute", r.compute.milliseconds > 0 ? r.fragment.milliseconds / r.compute.milliseconds : 0.0},
                      {"raster", {{"size", {raster.size.x, raster.size.y}},
                                  {"layers", raster.layers},
                                  {"triangles", raster.triangles},
                                  {"runs", raster.runs},
                                  {"compute_identifiers", raster.identifiers},
                                  {"raster_milliseconds", raster.raster_ms},
                                  {"compute_milliseconds", raster.compute_ms},
                                  {"raster_over_compute", raster.compute_ms > 0 ? raster.raster_ms / raster.compute_ms : 0.0},
                                  {"covered_pixels", raster.covered},
                                  {"depth_mismatches", raster.depth_mismatches},
                                  {"identifier_mismatches", raster.identifier_mismatches}}}};
  return j.dump(2) + "\n";
}

}  // namespace atrium
