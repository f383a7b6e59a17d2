// Light lists built on the CPU, for where the GPU cannot build them (the
// compute-free tier of issue 31: no compute shaders or storage buffers, as on
// WebGL2 and OpenGL 4.1): the same bins, the same test and the same layout as
// the GPU's LightIndexList (per bin a range of an index array, lights in light
// order), so that the shading passes read either alike. Each light visits only
// the clusters its sphere may reach (the C++ twin of clustered/assign.comp's
// slice_range, slice_cells and cell_run) and is listed in those whose box it
// touches, or the screen tiles whose frustum it reaches; the lights are split over worker threads where there are enough of
// them to pay for the threads, each writing its share of every bin in order.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "render/light_buffer.hpp"
#include "render/lighting/cluster_grid.hpp"

namespace atrium::lighting {

struct CpuLightLists {
  std::vector<glm::uvec2> ranges;     // per bin: first entry in `indices`, count (LightRange's layout)
  std::vector<std::uint32_t> indices;  // light indices, each bin's in light order
};

// Each thread takes at least this many lights: fewer are binned on the
// calling thread alone, where starting a thread (twice a call) would cost more
// than it saves. At 1,024 lights two threads already pay (1.9 -> 1.3 ms on
// dev-vm; docs/benchmarks.md, "CPU light binning").
inline constexpr std::size_t kLightsPerBinningThread = 256;

// The lists of every cluster of `grid` (as last updated: its boxes, slicing
// and projection; grid bounds, no pixel boxes) for `lights` seen through
// `view`, on up to `threads` threads (0: one per hardware thread).
[[nodiscard]] CpuLightLists bin_lights_in_clusters(std::span<const render::GpuLight> lights, const glm::mat4& view, const ClusterGrid& grid,
                                                   unsigned threads = 0);

// The lists of the viewport's `tile_size`-pixel screen tiles (row by row from
// the bottom, as tiled/tiles.glsl numbers them), each light listed in the
// tiles whose frustum (side planes through the eye, from the near to the far
// plane: no depth bounds, which would take the depth buffer back) its sphere
// reaches. `projection` must be symmetric, as gfx::perspective makes it.
[[nodiscard]] CpuLightLists bin_lights_in_tiles(std::span<const render::GpuLight> lights, const glm::mat4& view, const glm::mat4& projection,
                                                glm::ivec2 viewport, int tile_size, float near_plane, float far_plane,
                                                unsigned threads = 0);

}  // namespace atrium::lighting
