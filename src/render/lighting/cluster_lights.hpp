// The clustered light lists, shared by clustered-forward, clustered-deferred
// and the visibility buffer: the cluster grid sized for the frame, the marks
// that say which clusters hold visible positions (their pixel boxes, or active
// flags: shaders/clustered/mark_active.comp, and the blended surfaces by
// drawing), and the light assignment that fills the lists from them. Reads the
// positions shading will light (a G-buffer, or a depth buffer) and the lights;
// writes the lists. On the compute-free tier the lists come from the CPU
// (grid bounds: cpu_light_lists.hpp) as textures (render/storage_free.hpp).
#pragma once

#include <functional>
#include <memory>
#include <optional>

#include "components/technique_options.hpp"
#include "gfx/shader_library.hpp"
#include "render/frame/frame_context.hpp"
#include "render/frame_graph.hpp"
#include "render/lighting/cluster_grid.hpp"
#include "render/storage_free.hpp"

namespace atrium::lighting {

class ClusterLights {
 public:
  // Where the marks read the positions shading will light: a G-buffer's
  // (bound at units 0-4 by the caller) or depths along each pixel's centre ray (unit 0).
  enum class Positions { GBuffer, Depth };
  ClusterLights(gfx::ShaderLibrary& shaders, const TechniqueOptions& options, Positions positions);

  // Sizes the grid for the frame (--cluster-grid in pixels follows the size).
  void resize(glm::ivec2 size);
  // Fits the grid to the frame's projection, imports the lists into the graph
  // ("cluster-light-lists") and publishes how pixels map to them (the
  // light-bins view, where the lists are the GPU's). Returns the lists.
  render::ResourceId begin_frame(render::FrameGraph& graph, const render::FrameContext& frame);
  // The light assignment pass's body: marks the clusters from the positions
  // `bind_positions` binds and from the blended surfaces, then assigns the
  // lights (or bins them on the CPU on the compute-free tier).
  void assign(const render::PassResources& res, const render::FrameContext& frame, const render::FrameTargets& targets,
              const std::function<void()>& bind_positions);
  // Binds the grid's uniforms and its lists (the GPU's, or the CPU's textures) for shading.
  void bind() const;

  [[nodiscard]] const ClusterGrid& grid() const { return *grid_; }
  [[nodiscard]] bool compute_free() const { return compute_free_; }
  // Entries of the CPU's lists (compute-free tier) as last uploaded.
  [[nodiscard]] std::uint32_t cpu_entries() const { return cpu_lists_.entries(); }
  [[nodiscard]] LightIndexList& list() { return grid_->list(); }

 private:
  // Fills the per-cluster buffer assignment reads (pixel boxes, or active
  // flags) and returns it.
  GLuint mark_clusters(const render::PassResources& res, const render::FrameContext& frame, const render::FrameTargets& targets,
                       const std::function<void()>& bind_positions);

  bool compute_free_;
  bool pixel_bounds_;
  bool active_only_;
  ClusterGridSize grid_size_;
  ZSlicing z_slicing_;
  std::unique_ptr<ClusterGrid> grid_;  // sized by resize()
  std::optional<LightAssignmentPrograms> assign_;  // none on the compute-free tier
  gfx::ShaderProgram* mark_ = nullptr;             // nullptr on the compute-free tier
  gfx::ShaderProgram* mark_blended_ = nullptr;
  render::ListTextures cpu_lists_;                 // the compute-free tier's
};

}  // namespace atrium::lighting
