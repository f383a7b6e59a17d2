// Settings some lighting techniques read (--cluster-grid, --cluster-bounds,
// --active-clusters, --z-slicing, --gbuffer, --split-lighting, --msaa, --no-compute,
// --lighting-stage). Plain data, kept apart from the GL-facing technique interface so
// that RendererSettings can hold it; a change recreates the technique.
#pragma once

#include <array>
#include <string_view>

#include <glm/glm.hpp>

namespace atrium::lighting {

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

struct TechniqueOptions {
  glm::uvec3 cluster_grid{16, 9, 32};
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
  bool operator==(const TechniqueOptions&) const = default;
};

}  // namespace atrium::lighting
