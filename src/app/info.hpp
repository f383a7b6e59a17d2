// `atrium info SCENE [--json]`: what a scene holds and what loading it cost.
#pragma once

#include "base/box.hpp"

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "app/world.hpp"
#include "gfx/context.hpp"
#include "render/frame_graph.hpp"

namespace atrium {

struct SceneInfo {
  std::string scene;
  std::size_t entities = 0, mesh_instances = 0;
  std::size_t mesh_assets = 0, meshes = 0, primitives = 0;
  std::size_t triangles = 0;  // of the instances drawn
  std::size_t meshlets = 0, meshlet_primitives = 0;  // held by the mesh assets (assets/meshlets.hpp)
  std::size_t vertices = 0;   // held by the mesh assets (shared ones once), as uploaded
  std::size_t materials_opaque = 0, materials_mask = 0, materials_blend = 0;
  std::size_t textures = 0, texture_bytes = 0;
  std::size_t point_lights = 0, spot_lights = 0, directional_lights = 0;
  Box bounds;  // the scene's as declared (assets::SceneDescription::bounds); meaningless when empty()
  double parse_seconds = 0, decode_seconds = 0, upload_seconds = 0;
  std::size_t warnings = 0;
  // How tiled-deferred and the clustered modes cut a frame of `bins_size` into light-list bins.
  glm::ivec2 bins_size{0};
  glm::uvec2 tiles{0};
  std::uint32_t tile_pixels = 0;
  glm::uvec3 clusters{0};
  std::uint32_t cluster_tile_pixels = 0;  // the pixel grid's tile (--cluster-grid NpxxZ); 0: a fixed grid (XxYxZ)
  gfx::ContextInfo gl;  // the context the scene was uploaded to (which GPU, or a software renderer)
  // How the visibility buffer's resolve reaches the materials on this context
  // (--material-binding resolved), or why the binding asked for cannot run.
  MaterialBinding material_binding = MaterialBinding::Bound;
  std::string material_binding_refused;
  // --memory: per mode, the frame graph's render-target memory at `memory_size`
  // and every target and buffer its frame uses.
  struct ModeMemory {
    std::string mode;
    render::GraphMemory bytes;
    std::vector<render::ResourceUse> targets;
  };
  std::vector<ModeMemory> memory;
  glm::ivec2 memory_size{0};

  // Nothing to draw: no instance, or instances without triangles.
  [[nodiscard]] bool empty() const { return triangles == 0; }
};

// `size`: the frame size whose light-list bins it reports (--size).
[[nodiscard]] SceneInfo gather_info(World& world, const std::string& scene, glm::ivec2 size);
[[nodiscard]] std::string format_info_text(const SceneInfo& info);
[[nodiscard]] std::string format_info_json(const SceneInfo& info);

}  // namespace atrium
