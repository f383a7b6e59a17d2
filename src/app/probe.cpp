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
double mtriangles(std::uint32_t triangles, double milliseconds) {
  return milliseconds > 0 ? triangles / (milliseconds * 1e3) : 0.0;
}

nlohmann::json raster_json(const gfx::RasterProbeResult& r) {
  nlohmann::json rows = nlohmann::json::array();
  for (const gfx::RasterProbeRow& row : r.rows) {
    nlohmann::json entry = {{"cell_pixels", row.cell}, {"triangle_pixels", row.triangle_pixels()}, {"triangles", row.triangles}};
    if (row.skipped) {
      entry["skipped"] = true;
    } else {
      entry.update({{"raster_milliseconds", row.raster_ms},
                    {"compute_milliseconds", row.compute_ms},
                    {"raster_over_compute", row.compute_ms > 0 ? row.raster_ms / row.compute_ms : 0.0},
                    {"covered_pixels", row.covered},
                    {"depth_mismatches", row.depth_mismatches},
                    {"identifier_mismatches", row.identifier_mismatches}});
    }
    rows.push_back(std::move(entry));
  }
  return {{"size", {r.size.x, r.size.y}}, {"layers", r.layers}, {"runs", r.runs}, {"compute_identifiers", r.identifiers}, {"sizes", rows}};
}

}  // namespace

std::string format_probe_text(const gfx::StageProbeResult& r, const std::string& renderer) {
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
  return text;
}

std::string format_raster_probe_text(const gfx::RasterProbeResult& r) {
  std::string text;
  append(text, "triangles    %u layers over %dx%d, each passing the depth test; %s; median of %u runs\n", r.layers, r.size.x, r.size.y,
         r.identifiers ? "depth and identifier" : "depth and identifier by the raster pipeline, depth alone by compute (no 64-bit atomics)",
         r.runs);
  append(text, "  pixels a triangle  triangles   raster ms  Mtri/s   compute ms  Mtri/s   raster/compute  pixels that differ\n");
  for (const gfx::RasterProbeRow& row : r.rows) {
    if (row.skipped) {
      append(text, "  %17.1f  %9u  skipped: more than %u triangles\n", row.triangle_pixels(), row.triangles, gfx::kRasterProbeMaxTriangles);
      continue;
    }
    append(text, "  %17.1f  %9u  %10.3f  %6.0f  %11.3f  %6.0f  %14.2f  %llu of %llu", row.triangle_pixels(), row.triangles, row.raster_ms,
           mtriangles(row.triangles, row.raster_ms), row.compute_ms, mtriangles(row.triangles, row.compute_ms),
           row.compute_ms > 0 ? row.raster_ms / row.compute_ms : 0.0, static_cast<unsigned long long>(row.depth_mismatches),
           static_cast<unsigned long long>(row.covered));
    if (r.identifiers) append(text, " (identifier: %llu)", static_cast<unsigned long long>(row.identifier_mismatches));
    text += "\n";
  }
  return text;
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
                      {"raster", raster_json(raster)}};
  return j.dump(2) + "\n";
}

}  // namespace atrium
