#include "render/lighting/cpu_light_lists.hpp"

#include <algorithm>
#include <cmath>

#include "base/parallel.hpp"

namespace atrium::lighting {
namespace {

// Twins of clustered/assign.comp's candidate walk (without pixel boxes, whose
// pad only widens the walk): which clusters a light may reach.
struct ClusterWalk {
  const ClusterGrid& grid;
  glm::uvec3 dims = grid.dims();
  float near_plane = grid.near_plane();
  glm::vec2 scale{1.0f / grid.projection()[0][0], 1.0f / grid.projection()[1][1]};

  [[nodiscard]] std::uint32_t cluster_at(std::uint32_t x, std::uint32_t y, std::uint32_t z) const { return (z * dims.y + y) * dims.x + x; }

  // cell_run: the columns (or rows) of a slice between depths d0 and d1 whose
  // boxes may reach [lo, hi], one more on each side for rounding.
  static glm::uvec2 cell_run(float lo, float hi, float d0, float d1, float scale, std::uint32_t cells) {
    const float t = lo / scale, u = hi / scale;
    const float least_right = t >= 0.0f ? t / d1 : t / d0;
    const float most_left = u >= 0.0f ? u / d0 : u / d1;
    const auto n = static_cast<float>(cells);
    const float first = std::clamp(std::ceil((least_right + 1.0f) * 0.5f * n) - 2.0f, 0.0f, n - 1.0f);
    const float last = std::clamp(std::floor((most_left + 1.0f) * 0.5f * n) + 1.0f, 0.0f, n - 1.0f);
    return {static_cast<std::uint32_t>(first), static_cast<std::uint32_t>(last)};
  }

  // Calls visit(cluster) for every cluster the view-space sphere touches (a
  // negative radius touches all of them), in the GPU's candidate order.
  template <typename Visit>
  void each_touched(glm::vec4 sphere, Visit visit) const {
    const std::vector<ClusterBox>& boxes = grid.boxes();
    if (sphere.w < 0.0f) {
      for (std::uint32_t c = 0; c < boxes.size(); ++c) visit(c);
      return;
    }
    const glm::vec3 centre(sphere);
    const float far_depth = -sphere.z + sphere.w;
    if (far_depth < near_plane * 0.5f) return;
    // The same slack as the GPU's: a slice more each way, a millimetre per metre more reach.
    const float reach = sphere.w + 2.0f * 1e-3f * (1.0f + std::max(far_depth, 0.0f));
    const std::uint32_t first_slice = static_cast<std::uint32_t>(std::max(static_cast<int>(grid.slice_of(-sphere.z - sphere.w)) - 1, 0));
    const std::uint32_t last_slice = std::min(grid.slice_of(far_depth) + 1, dims.z - 1);
    for (std::uint32_t z = first_slice; z <= last_slice; ++z) {
      const ClusterBox& slice = boxes[cluster_at(0, 0, z)];
      const float d0 = -slice.hi.z, d1 = -slice.lo.z;
      const glm::uvec2 columns = cell_run(centre.x - reach, centre.x + reach, d0, d1, scale.x, dims.x);
      const glm::uvec2 rows = cell_run(centre.y - reach, centre.y + reach, d0, d1, scale.y, dims.y);
      for (std::uint32_t y = rows.x; y <= rows.y; ++y) {
        for (std::uint32_t x = columns.x; x <= columns.y; ++x) {
          const std::uint32_t cluster = cluster_at(x, y, z);
          const glm::vec3 nearest = glm::clamp(centre, glm::vec3(boxes[cluster].lo), glm::vec3(boxes[cluster].hi)) - centre;
          if (glm::dot(nearest, nearest) <= sphere.w * sphere.w) visit(cluster);
        }
      }
    }
  }
};

// GLSL twin: view_sphere in common/light_scatter.glsl.
glm::vec4 view_sphere(const render::GpuLight& light, const glm::mat4& view) {
  const bool everywhere = light.color_kind.w == static_cast<float>(render::GpuLightKind::Directional);
  return glm::vec4(glm::vec3(view * glm::vec4(glm::vec3(light.position_radius), 1.0f)), everywhere ? -1.0f : light.position_radius.w);
}

// The lists of `bins` bins, each light listed in the bins each_touched(sphere,
// visit) visits, split over threads by runs of lights.
template <typename EachTouched>
CpuLightLists bin_lights(std::span<const render::GpuLight> lights, const glm::mat4& view, std::size_t bins, unsigned threads,
                         const EachTouched& each_touched) {
  if (threads == 0) threads = hardware_threads();
  const std::size_t shares = share_count(lights.size(), kLightsPerBinningThread, threads);

  // Each share (a run of lights in order) keeps the bins its lights touch,
  // light by light, and counts them per bin.
  struct Share {
    std::size_t first_light = 0, end_light = 0;
    std::vector<std::uint32_t> touched;    // bins, light after light
    std::vector<std::uint32_t> per_light;  // how many of `touched` each light has
    std::vector<std::uint32_t> counts;     // per bin; then this share's cursor in each bin
  };
  std::vector<Share> split(shares);
  auto gather = [&](Share& share) {
    share.counts.assign(bins, 0);
    share.per_light.reserve(share.end_light - share.first_light);
    for (std::size_t l = share.first_light; l < share.end_light; ++l) {
      const std::size_t before = share.touched.size();
      each_touched(view_sphere(lights[l], view), [&](std::uint32_t bin) {
        share.touched.push_back(bin);
        ++share.counts[bin];
      });
      share.per_light.push_back(static_cast<std::uint32_t>(share.touched.size() - before));
    }
  };
  for (std::size_t s = 0; s < shares; ++s) {
    const ShareRange range = share_range(lights.size(), shares, s);
    split[s].first_light = range.begin;
    split[s].end_light = range.end;
  }
  run_in_parallel(shares, [&](std::size_t s) { gather(split[s]); });

  // A bin's entries: every share's, in share (so light) order.
  CpuLightLists lists;
  lists.ranges.resize(bins);
  std::uint32_t total = 0;
  for (std::size_t b = 0; b < bins; ++b) {
    lists.ranges[b].x = total;
    for (Share& share : split) {
      const std::uint32_t count = share.counts[b];
      share.counts[b] = total;
      total += count;
    }
    lists.ranges[b].y = total - lists.ranges[b].x;
  }
  lists.indices.resize(total);
  auto write = [&](Share& share) {
    std::size_t next = 0;
    for (std::size_t l = share.first_light; l < share.end_light; ++l) {
      const std::uint32_t count = share.per_light[l - share.first_light];
      for (std::uint32_t k = 0; k < count; ++k) lists.indices[share.counts[share.touched[next++]]++] = static_cast<std::uint32_t>(l);
    }
  };
  run_in_parallel(shares, [&](std::size_t s) { write(split[s]); });
  return lists;
}

// Which screen tiles a light may reach: those under its sphere's screen
// rectangle (all of them for a sphere across the near plane) whose four side
// planes through the eye it does not lie wholly outside of.
struct TileWalk {
  glm::uvec2 tiles;
  glm::vec2 tile_ndc;  // a tile's width and height in NDC
  glm::vec2 scale;     // view-space x and y per unit of NDC at depth 1 (a symmetric frustum)
  float near_plane, far_plane;

  template <typename Visit>
  void each_touched(glm::vec4 sphere, Visit visit) const {
    const std::uint32_t count = tiles.x * tiles.y;
    if (sphere.w < 0.0f) {
      for (std::uint32_t t = 0; t < count; ++t) visit(t);
      return;
    }
    const glm::vec3 c(sphere);
    const float r = sphere.w, depth = -c.z;
    if (depth + r < near_plane || depth - r > far_plane) return;
    glm::uvec2 lo(0), hi = tiles - 1u;
    if (depth - r > near_plane) {
      // The rectangle of the sphere's view-space box, its nearest face the widest.
      const float nearest = depth - r;
      const glm::vec2 low = (glm::vec2(c) - r) / (scale * nearest), high = (glm::vec2(c) + r) / (scale * nearest);
      const glm::vec2 low_far = (glm::vec2(c) - r) / (scale * (depth + r)), high_far = (glm::vec2(c) + r) / (scale * (depth + r));
      const glm::vec2 ndc_low = glm::min(low, low_far), ndc_high = glm::max(high, high_far);
      if (ndc_high.x < -1.0f || ndc_high.y < -1.0f || ndc_low.x > 1.0f || ndc_low.y > 1.0f) return;
      const glm::vec2 last = glm::vec2(tiles) - 1.0f;
      // One tile more each way for rounding.
      lo = glm::uvec2(glm::clamp(glm::floor((ndc_low + 1.0f) / tile_ndc) - 1.0f, glm::vec2(0.0f), last));
      hi = glm::uvec2(glm::clamp(glm::floor((ndc_high + 1.0f) / tile_ndc) + 1.0f, glm::vec2(0.0f), last));
    }
    for (std::uint32_t y = lo.y; y <= hi.y; ++y) {
      // Planes x = a s_x (-z) through the eye: inside the tile when a point is
      // right of its left plane and left of its right one (and so for y).
      const float bottom = -1.0f + static_cast<float>(y) * tile_ndc.y, top = bottom + tile_ndc.y;
      if (!inside_slab(c.y, c.z, bottom * scale.y, top * scale.y, r)) continue;
      for (std::uint32_t x = lo.x; x <= hi.x; ++x) {
        const float left = -1.0f + static_cast<float>(x) * tile_ndc.x, right = left + tile_ndc.x;
        if (inside_slab(c.x, c.z, left * scale.x, right * scale.x, r)) visit(y * tiles.x + x);
      }
    }
  }

  // Whether a sphere (coordinate u, view z, radius r) reaches the wedge between
  // the planes u = low (-z) and u = high (-z) through the eye.
  static bool inside_slab(float u, float z, float low, float high, float r) {
    const float above_low = (u + low * z) / std::sqrt(1.0f + low * low);     // distance on the inner side of u = low (-z)
    const float below_high = -(u + high * z) / std::sqrt(1.0f + high * high);
    return above_low >= -r && below_high >= -r;
  }
};

}  // namespace

CpuLightLists bin_lights_in_clusters(std::span<const render::GpuLight> lights, const glm::mat4& view, const ClusterGrid& grid, unsigned threads) {
  const ClusterWalk walk{grid};
  return bin_lights(lights, view, grid.boxes().size(), threads,
                    [&](glm::vec4 sphere, const auto& visit) { walk.each_touched(sphere, visit); });
}

CpuLightLists bin_lights_in_tiles(std::span<const render::GpuLight> lights, const glm::mat4& view, const glm::mat4& projection, glm::ivec2 viewport,
                                  int tile_size, float near_plane, float far_plane, unsigned threads) {
  const glm::uvec2 tiles = (glm::uvec2(viewport) + glm::uvec2(tile_size - 1)) / glm::uvec2(tile_size);
  const TileWalk walk{tiles, 2.0f * static_cast<float>(tile_size) / glm::vec2(viewport),
                      glm::vec2(1.0f / projection[0][0], 1.0f / projection[1][1]), near_plane, far_plane};
  return bin_lights(lights, view, std::size_t{tiles.x} * tiles.y, threads,
                    [&](glm::vec4 sphere, const auto& visit) { walk.each_touched(sphere, visit); });
}

}  // namespace atrium::lighting
