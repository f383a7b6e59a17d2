#include "app/info.hpp"

#include <cstdio>

#include <nlohmann/json.hpp>

#include "base/format.hpp"
#include "components/frame_resources.hpp"
#include "components/light.hpp"
#include "components/mesh_instance.hpp"
#include "gfx/limits.hpp"
#include "render/techniques/tiled/tiled.hpp"
#include "render/techniques/visibility/visibility.hpp"

namespace atrium {

SceneInfo gather_info(World& world, const std::string& scene, glm::ivec2 size) {
  SceneInfo info;
  info.scene = scene;
  ecs::Registry& registry = world.registry();
  const auto& assets = registry.resource<assets::AssetManager>();
  info.entities = registry.alive_count();
  info.mesh_assets = assets.mesh_asset_count();
  for (std::size_t a = 0; a < assets.mesh_asset_count(); ++a) {
    const assets::MeshAsset& asset = assets.mesh_asset(assets::MeshAssetHandle{static_cast<std::uint32_t>(a)});
    info.meshes += asset.meshes.size();
    info.vertices += asset.vertex_count();
    for (const auto& mesh : asset.meshes) {
      info.primitives += mesh.primitives.size();
      for (const auto& p : mesh.primitives) {
        info.meshlets += p.meshlets.size();
        info.meshlet_primitives += !p.meshlets.empty();
      }
    }
    for (const auto& m : asset.materials) {
      (m.alpha_mode == assets::AlphaMode::Blend ? info.materials_blend
       : m.alpha_mode == assets::AlphaMode::Mask ? info.materials_mask
                                                 : info.materials_opaque)++;
    }
  }
  registry.view<MeshInstance>().each([&](const MeshInstance& instance) {
    ++info.mesh_instances;
    const auto& asset = assets.mesh_asset(instance.asset);
    if (instance.mesh >= asset.meshes.size()) return;
    for (const auto& p : asset.meshes[instance.mesh].primitives) info.triangles += p.indices.size() / 3;
  });
  info.textures = assets.texture_count();
  for (std::size_t t = 0; t < assets.texture_count(); ++t) {
    info.texture_bytes += assets.texture(assets::TextureHandle{static_cast<std::uint32_t>(t)}).bytes();
  }
  registry.view<LightColor>().each([&](ecs::Entity e, const LightColor&) {
    if (registry.has<DirectionalLight>(e)) ++info.directional_lights;
    else if (registry.has<SpotCone>(e)) ++info.spot_lights;
    else ++info.point_lights;
  });
  info.bounds = world.scene().bounds;
  info.parse_seconds = world.load_report().timings.parse_seconds;
  info.decode_seconds = world.load_report().timings.decode_seconds;
  info.upload_seconds = world.upload_seconds();
  info.warnings = world.load_report().warnings.size();
  info.bins_size = size;
  info.tile_pixels = techniques::kTileSize;
  info.tiles = (glm::uvec2(glm::max(info.bins_size, glm::ivec2(1))) + glm::uvec2(techniques::kTileSize - 1)) / glm::uvec2(techniques::kTileSize);
  const ClusterGridSize grid = registry.resource<RendererSettings>().technique_options.cluster_grid;
  info.clusters = grid.at(info.bins_size);
  info.cluster_tile_pixels = grid.tile_pixels;
  try {
    info.material_binding = techniques::resolve_material_binding(registry.resource<RendererSettings>().technique_options);
  } catch (const gfx::ResourceLimitError& e) {
    info.material_binding_refused = e.what();
  }
  return info;
}

std::string format_info_text(const SceneInfo& i) {
  char bounds[256];
  if (i.empty()) {
    std::snprintf(bounds, sizeof bounds, "none: the scene is empty (nothing to draw)");
  } else {
    std::snprintf(bounds, sizeof bounds, "(%.2f, %.2f, %.2f) to (%.2f, %.2f, %.2f)", i.bounds.min.x, i.bounds.min.y, i.bounds.min.z,
                  i.bounds.max.x, i.bounds.max.y, i.bounds.max.z);
  }
  char buffer[2048];
  std::snprintf(buffer, sizeof buffer,
                "scene        %s\n"
                "entities     %zu (%zu mesh instances, %zu lights, 1 camera)\n"
                "mesh assets  %zu with %zu meshes, %zu primitives and %zu vertices\n"
                "drawn        %zu triangles\n"
                "meshlets     %zu in %zu large primitives (culled one by one)\n"
                "materials    %zu: %zu opaque, %zu mask, %zu blend\n"
                "textures     %zu (%.1f MiB in memory, compressed ones as stored)\n"
                "lights       %zu: %zu point, %zu spot, %zu directional\n"
                "bounds       %s\n"
                "load time    parse %.3f s, decode %.3f s, upload %.3f s\n"
                "warnings     %zu\n"
                "gl           %s (%s), OpenGL %s, %s\n",
                i.scene.c_str(), i.entities, i.mesh_instances, i.point_lights + i.spot_lights + i.directional_lights,
                i.mesh_assets, i.meshes, i.primitives, i.vertices, i.triangles, i.meshlets, i.meshlet_primitives,
                i.materials_opaque + i.materials_mask + i.materials_blend, i.materials_opaque, i.materials_mask,
                i.materials_blend, i.textures, static_cast<double>(i.texture_bytes) / (1024.0 * 1024.0),
                i.point_lights + i.spot_lights + i.directional_lights, i.point_lights, i.spot_lights, i.directional_lights,
                bounds,
                i.parse_seconds, i.decode_seconds, i.upload_seconds, i.warnings, i.gl.renderer.c_str(), i.gl.vendor.c_str(),
                i.gl.version.c_str(), i.gl.platform.c_str());
  std::string text = buffer;
  const std::string grid = i.cluster_tile_pixels ? std::to_string(i.cluster_tile_pixels) + "-pixel tiles, at least " +
                                                       std::to_string(kMinPixelGridTiles.x) + "x" +
                                                       std::to_string(kMinPixelGridTiles.y) + ", --cluster-grid"
                                                 : "fixed, --cluster-grid";
  char bins[256];
  std::snprintf(bins, sizeof bins, "light bins   at %dx%d: tiles %ux%u of %u px; clusters %ux%ux%u (%s)\n", i.bins_size.x, i.bins_size.y,
                i.tiles.x, i.tiles.y, i.tile_pixels, i.clusters.x, i.clusters.y, i.clusters.z, grid.c_str());
  text += bins;
  if (!i.material_binding_refused.empty()) {
    text += "vis buffer   refused: " + i.material_binding_refused + "\n";
  } else if (i.material_binding == MaterialBinding::Bindless) {
    text += "vis buffer   materials bindless (GL_ARB_bindless_texture: one resolve dispatch, textures by handle)\n";
  } else {
    text += "vis buffer   materials bound (one resolve dispatch per material, its textures bound)\n";
  }
  if (!i.memory.empty()) {
    char line[256];
    std::snprintf(line, sizeof line, "render targets at %dx%d (long-lived; transient as allocated, unshared):\n", i.memory_size.x,
                  i.memory_size.y);
    text += line;
    for (const SceneInfo::ModeMemory& m : i.memory) {
      std::snprintf(line, sizeof line, "  %-24s %10s; %s (%s)\n", m.mode.c_str(), format_bytes(static_cast<double>(m.bytes.imported_bytes)).c_str(),
                    format_bytes(static_cast<double>(m.bytes.aliased_bytes)).c_str(),
                    format_bytes(static_cast<double>(m.bytes.transient_bytes)).c_str());
      text += line;
      for (const render::ResourceUse& target : m.targets) {
        std::snprintf(line, sizeof line, "    %-26s %-34s %10s  %s\n", target.name.c_str(), target.description.c_str(),
                      format_bytes(static_cast<double>(target.bytes)).c_str(), target.imported ? "long-lived" : "transient");
        text += line;
      }
    }
  }
  return text;
}

std::string format_info_json(const SceneInfo& i) {
  nlohmann::json j = {
      {"scene", i.scene},
      {"entities", i.entities},
      {"mesh_instances", i.mesh_instances},
      {"mesh_assets", i.mesh_assets},
      {"meshes", i.meshes},
      {"primitives", i.primitives},
      {"triangles", i.triangles},
      {"meshlets", i.meshlets},
      {"meshlet_primitives", i.meshlet_primitives},
      {"vertices", i.vertices},
      {"materials", {{"opaque", i.materials_opaque}, {"mask", i.materials_mask}, {"blend", i.materials_blend}}},
      {"textures", i.textures},
      {"texture_bytes", i.texture_bytes},
      {"lights", {{"point", i.point_lights}, {"spot", i.spot_lights}, {"directional", i.directional_lights}}},
      {"empty", i.empty()},
      {"bounds", i.empty() ? nlohmann::json(nullptr)
                           : nlohmann::json{{"min", {i.bounds.min.x, i.bounds.min.y, i.bounds.min.z}},
                                            {"max", {i.bounds.max.x, i.bounds.max.y, i.bounds.max.z}}}},
      {"load_seconds", {{"parse", i.parse_seconds}, {"decode", i.decode_seconds}, {"upload", i.upload_seconds}}},
      {"warnings", i.warnings},
      {"light_bins",
       {{"size", {i.bins_size.x, i.bins_size.y}},
        {"tiles", {i.tiles.x, i.tiles.y}},
        {"tile_pixels", i.tile_pixels},
        {"clusters", {i.clusters.x, i.clusters.y, i.clusters.z}},
        {"cluster_tile_pixels", i.cluster_tile_pixels}}},
      {"material_binding", i.material_binding_refused.empty() ? std::string(kMaterialBindingNames[static_cast<std::size_t>(i.material_binding)])
                                                              : i.material_binding_refused},
      {"gl", {{"renderer", i.gl.renderer}, {"vendor", i.gl.vendor}, {"version", i.gl.version}, {"platform", i.gl.platform}}}};
  if (!i.memory.empty()) {
    nlohmann::json modes = nlohmann::json::array();
    for (const SceneInfo::ModeMemory& m : i.memory) {
      nlohmann::json targets = nlohmann::json::array();
      for (const render::ResourceUse& target : m.targets) {
        targets.push_back({{"name", target.name}, {"kind", target.kind == render::ResourceKind::Texture ? "texture" : "buffer"},
                           {"description", target.description}, {"bytes", target.bytes}, {"long_lived", target.imported}});
      }
      modes.push_back({{"mode", m.mode}, {"imported_bytes", m.bytes.imported_bytes}, {"transient_bytes", m.bytes.transient_bytes},
                       {"aliased_bytes", m.bytes.aliased_bytes}, {"targets", targets}});
    }
    j["render_targets"] = {{"size", {i.memory_size.x, i.memory_size.y}}, {"modes", modes}};
  }
  return j.dump(2) + "\n";
}

}  // namespace atrium
