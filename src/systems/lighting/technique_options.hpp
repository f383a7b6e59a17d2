// Settings some lighting techniques read (--cluster-grid, --active-clusters).
// Plain data, kept apart from the GL-facing technique interface so that
// RendererSettings can hold it; a change recreates the technique.
#pragma once

#include <glm/glm.hpp>

namespace atrium::lighting {

// Settings some techniques read (--cluster-grid, --active-clusters); a change
// recreates the technique.
struct TechniqueOptions {
  glm::uvec3 cluster_grid{16, 9, 24};
  bool active_clusters = false;
  bool operator==(const TechniqueOptions&) const = default;
};

}  // namespace atrium::lighting
