// Settings some lighting techniques read (--cluster-grid, --cluster-bounds,
// --active-clusters, --z-slicing, --gbuffer, --split-lighting, --msaa, --no-compute,
// --lighting-stage, --light-assignment, --material-binding). Plain data, kept apart from the GL-facing technique interface so
// that RendererSettings can hold it; a change recreates the technique.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

#include <glm/glm.hpp>

namespace atrium {

// Which G-buffer the deferred modes write: the reference's five targets, or two
// packed targets with position reconstructed from depth (gbuffer.glsl). Thin is
// the light pre-pass's own (normal, roughness, distance), not a --gbuffer
// choice: kGBufferLayoutNames lists only the choices.
enum class GBufferLayout { Full, Compact, Thin };
inline constexpr std::array<std::string_view, 2> kGBufferLayoutNames{"full", "compact"};

// What the clustered modes test lights against: each cluster's box of the
// pixels it holds this frame (tight, the default), or its whole slice of the
// view frustum (the grid).
enum class ClusterBounds { Pixels, Grid };
inline constexpr std::array<std::string_view, 2> kClusterBoundsNames{"pixels", "grid"};

// How the clustered modes cut view depth into slices (shaders/common/clusters.glsl):
// log, the default, gives the first slice the depths from the near plane to ten
// near-plane distances and cuts the rest logarithmically; plain-log is logarithmic
// from the near plane itself; uniform cuts equal thicknesses.
enum class ZSlicing { Log, Uniform, PlainLog };
inline constexpr std::array<std::string_view, 3> kZSlicingNames{"log", "uniform", "plain-log"};

// Where the full-screen passes of a frame run (--lighting-stage): the lighting
// passes of deferred, deferred-radius, tiled-deferred and clustered-deferred,
// and the tone map of every mode. Fragment: full-screen triangles; Compute:
// one invocation per pixel, stored with imageStore (render/lighting/lighting_pass.hpp).
// Automatic takes compute on hardware GPUs, where it reaches every SM (on an
// H200 fragment shaders run on 4 of its 132: docs/benchmarks.md), and the
// fragment stage on software renderers, where it measured faster, with MSAA,
// which the compute stage does not shade per sample, and on the compute-free tier.
enum class LightingStage { Automatic, Fragment, Compute };
inline constexpr std::array<std::string_view, 3> kLightingStageNames{"auto", "fragment", "compute"};

// How the tiled and clustered modes build their light lists
// (render/lighting/light_index_list.hpp). Scatter: each light visits the bins
// its sphere may reach (cost follows the lights' hits; wins with many small
// lights). Gather: each bin tests every light (cost follows bins times lights,
// no atomics, no sort; wins where few lights each reach much of the screen).
// Automatic picks one per frame from the lists' last density (the share of
// bin-light pairs that are hits, as earlier frames reported it).
enum class LightAssignment { Automatic, Scatter, Gather };
inline constexpr std::array<std::string_view, 3> kLightAssignmentNames{"auto", "scatter", "gather"};
// How a frame's lists were built, for the stats lines: lists that no GPU
// assignment built (the compute-free tier's) are binned on the CPU.
inline std::string_view light_assignment_label(LightAssignment ran) {
  return ran == LightAssignment::Automatic ? std::string_view("binned on the CPU") : kLightAssignmentNames[static_cast<std::size_t>(ran)];
}

// How the visibility buffer's resolve reaches the materials' textures
// (render/techniques/visibility/visibility.hpp). Bound: classification lists
// each material's tiles and one indirect dispatch per material runs over them
// with its textures bound (Burns and Hunt's per-material passes, for GL without
// bindless textures). Bindless: one dispatch over every tile; each work group
// shades the materials its tile shows in turn, sampling by handle
// (ARB_bindless_texture): no classification, no per-material dispatches.
// Automatic takes bindless where the context has the extension.
enum class MaterialBinding { Automatic, Bound, Bindless };
inline constexpr std::array<std::string_view, 3> kMaterialBindingNames{"auto", "bound", "bindless"};

// The clustered modes' grid (--cluster-grid): square screen tiles of
// `tile_pixels` (the default) with dims.z depth slices, so that a cluster
// covers as many pixels at 1920x1080 as at 320x180 and its list stays as
// tight, but never fewer than kMinPixelGridTiles across and down (small frames
// keep the 16x9 tiles of the fixed grid before); or (tile_pixels 0) a fixed
// number of clusters per axis, dims. 24 pixels keep the clustered lists
// tighter than tiled-deferred's 16-pixel tiles at every size and light count
// measured, 32 did not at 320x180 with 131,072 lights (docs/techniques.md,
// "Cluster tiles in pixels").
inline constexpr std::uint32_t kClusterTilePixels = 24;
inline constexpr glm::uvec2 kMinPixelGridTiles{16, 9};
struct ClusterGridSize {
  glm::uvec3 dims{0, 0, 32};
  std::uint32_t tile_pixels = kClusterTilePixels;

  [[nodiscard]] static ClusterGridSize fixed(glm::uvec3 clusters) { return {clusters, 0}; }
  [[nodiscard]] static ClusterGridSize pixels(std::uint32_t tile, std::uint32_t slices) { return {{0, 0, slices}, tile}; }
  // Tiles grow past tile_pixels where the grid would pass kMaxPixelClusters
  // (beyond about 2880x1620 at 24 pixels and 32 slices), for the boxes, lists
  // and scan grow with the clusters, not with what they hold.
  static constexpr std::uint64_t kMaxPixelClusters = 1u << 18;
  // The clusters per axis for a frame of `size` pixels.
  [[nodiscard]] glm::uvec3 at(glm::ivec2 size) const {
    if (tile_pixels == 0) return dims;
    const glm::uvec2 pixels(glm::max(size, glm::ivec2(1)));
    for (std::uint32_t tile = tile_pixels;; ++tile) {
      const glm::uvec2 tiles = glm::max((pixels + glm::uvec2(tile - 1)) / glm::uvec2(tile), kMinPixelGridTiles);
      if (std::uint64_t{tiles.x} * tiles.y * dims.z <= kMaxPixelClusters || tile >= glm::max(pixels.x, pixels.y)) return {tiles, dims.z};
    }
  }
  bool operator==(const ClusterGridSize&) const = default;
};

struct TechniqueOptions {
  ClusterGridSize cluster_grid;
  ClusterBounds cluster_bounds = ClusterBounds::Pixels;
  bool active_clusters = false;  // grid bounds: only clusters holding a visible pixel get lights
  ZSlicing z_slicing = ZSlicing::Log;
  GBufferLayout gbuffer_layout = GBufferLayout::Full;
  // Deferred modes also write the diffuse and the specular light sums to targets
  // of their own (FrameTargets::diffuse_light, specular_light).
  bool split_lighting = false;
  // MSAA samples per pixel (--msaa); 1 is off. Every frame target is then
  // multisampled and the deferred modes shade per sample on the edges their
  // G-buffer pass marks (shaders/common/msaa.glsl, sample_rate.hpp).
  int msaa = 1;
  // The compute-free tier (--no-compute, and by itself on a context without
  // compute shaders or storage buffers): records in textures
  // (render/storage_free.hpp), draws issued from the CPU, no occlusion
  // culling; modes that need compute say so.
  bool compute_free = false;
  LightingStage lighting_stage = LightingStage::Automatic;
  LightAssignment light_assignment = LightAssignment::Automatic;
  MaterialBinding material_binding = MaterialBinding::Automatic;
  bool operator==(const TechniqueOptions&) const = default;
};

}  // namespace atrium
