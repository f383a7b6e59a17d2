// Settings some lighting techniques read (--cluster-grid, --active-clusters,
// --gbuffer). Plain data, kept apart from the GL-facing technique interface so
// that RendererSettings can hold it; a change recreates the technique.
#pragma once

#include <array>
#include <string_view>

#include <glm/glm.hpp>

namespace atrium::lighting {

// Which G-buffer the deferred modes write: the reference's five targets, or two
// packed targets with position reconstructed from depth (gbuffer.glsl).
enum class GBufferLayout { Full, Compact };
inline constexpr std::array<std::string_view, 2> kGBufferLayoutNames{"full", "compact"};

struct TechniqueOptions {
  glm::uvec3 cluster_grid{16, 9, 24};
  bool active_clusters = false;
  GBufferLayout gbuffer_layout = GBufferLayout::Full;
  bool operator==(const TechniqueOptions&) const = default;
};

}  // namespace atrium::lighting
