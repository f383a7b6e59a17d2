// Where the GPU runs each shader stage, and what that costs: one pass of
// arithmetic per pixel run as a compute dispatch and as a full-screen fragment
// pass, each counted per SM (NVIDIA's GL_NV_shader_thread_group: gl_SMIDNV,
// GL_SM_COUNT_NV, where the driver has it) and timed; and small triangles
// rasterised by the raster pipeline and by compute. It exists because a
// Hopper GPU runs fragment shaders on few of its SMs and compute on all of them
// (docs/benchmarks.md): `atrium probe` measures that instead of assuming it.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace atrium::gfx {

struct StageReach {
  double milliseconds = 0;                  // the timed pass, median of the runs
  std::vector<std::uint32_t> invocations;   // the census pass's invocations per SM id; empty without SM ids
  // SMs that ran at least one invocation; 0 without SM ids.
  [[nodiscard]] std::uint32_t sms_reached() const;
};

struct StageProbeResult {
  glm::ivec2 size{0};
  std::uint32_t iterations = 0;          // loop iterations per pixel, 16 flops each
  std::uint32_t runs = 0;                // timed runs per stage
  bool sm_ids = false;                   // GL_NV_shader_thread_group is present
  std::uint32_t sm_count = 0;            // GL_SM_COUNT_NV (0 without the extension)
  std::uint32_t warp_size = 0, warps_per_sm = 0;
  std::string timing;                    // how passes were timed (PassTimer::method_name)
  StageReach compute, fragment;
  // Floating-point operations the timed pass does (pixels x iterations x 16).
  [[nodiscard]] double flops() const;
};

// Runs the probe on the current context, which must have compute shaders and
// storage buffers (throws std::runtime_error naming what is missing).
[[nodiscard]] StageProbeResult run_stage_probe(glm::ivec2 size, std::uint32_t iterations = 256, std::uint32_t runs = 5);

// The visibility buffer's geometry work for small triangles, done twice: by
// the raster pipeline (depth test, the identifier written) and by a compute
// shader that rasterises a triangle an invocation (shaders/probe/raster.comp,
// as Nanite does small triangles). Where the raster pipeline reaches few SMs,
// this is what moving the geometry pass to compute would gain, and the
// triangle sizes say up to where; the two pictures are compared pixel by
// pixel, so the compute side is known to do the same work.
struct RasterProbeRow {
  int cell = 0;                 // square cells of this many pixels a side, two triangles each
  std::uint32_t triangles = 0;  // in all layers
  double raster_ms = 0, compute_ms = 0;  // medians of the runs
  // Pixels where the two disagree: one covered and the other not, or the
  // nearest depths apart by more than 1e-5; with identifiers, a different triangle.
  std::uint64_t depth_mismatches = 0, identifier_mismatches = 0;
  std::uint64_t covered = 0;  // pixels the raster side covered
  bool skipped = false;       // more than kRasterProbeMaxTriangles: not drawn
  [[nodiscard]] double triangle_pixels() const { return cell * cell / 2.0; }
};

struct RasterProbeResult {
  glm::ivec2 size{0};
  std::uint32_t layers = 0;  // full-image sheets of triangles, drawn farthest first (each passes the depth test)
  std::uint32_t runs = 0;
  // The compute side keeps depth and identifier in one 64-bit texel
  // (GL_NV_shader_atomic_int64, as on NVIDIA); without it, depth alone.
  bool identifiers = false;
  std::string timing;
  std::vector<RasterProbeRow> rows;  // one per cell size, smallest first
};

// Cells of 2 pixels give triangles of 2 pixels, the twelve-courtyard grid's
// density at 1080p; 16 pixels, 128-pixel triangles, where one invocation a
// triangle is expected to lose.
inline constexpr int kRasterProbeCells[] = {2, 4, 8, 16};
// A size's rows past this many triangles are skipped (at 4K, 2-pixel cells:
// 12.4 million, a third of a gigabyte of vertices and indices on each side).
inline constexpr std::uint32_t kRasterProbeMaxTriangles = 1u << 23;

// Runs it on the current context (compute shaders and storage buffers, as
// run_stage_probe).
[[nodiscard]] RasterProbeResult run_raster_probe(glm::ivec2 size, std::span<const int> cells = kRasterProbeCells,
                                                 std::uint32_t layers = 3, std::uint32_t runs = 5);

}  // namespace atrium::gfx
