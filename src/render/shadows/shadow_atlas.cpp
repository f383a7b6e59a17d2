#include "render/shadows/shadow_atlas.hpp"

#include <algorithm>
#include <bit>
#include <map>
#include <tuple>

#include "components/light.hpp"
#include "components/mesh_instance.hpp"
#include "components/transform.hpp"
#include "gfx/depth.hpp"
#include "gfx/limits.hpp"
#include "assets/meshlets.hpp"
#include "base/frustum.hpp"

namespace atrium::shadows {
namespace {

bool box_meets_sphere(const Box& box, glm::vec3 centre, float radius) {
  const glm::vec3 nearest = glm::clamp(centre, box.min, box.max);
  const glm::vec3 d = nearest - centre;
  return glm::dot(d, d) <= radius * radius;
}


// What a map depends on besides geometry: position, reach, direction, cone, kind.
bool same_light(const render::GpuLight& a, const render::GpuLight& b) {
  return a.position_radius == b.position_radius && a.direction == b.direction && a.color_kind.w == b.color_kind.w &&
         glm::vec2(a.spot) == glm::vec2(b.spot);
}

// Whether a light at `position` sits in the glowing surface with this box: a
// lamp's glass or bulb around its light, which would otherwise shadow all of
// it. The box grows by a tenth of its size (and a centimetre) for lights
// placed on the glass rather than in it.
bool inside_lamp(const Box& box, glm::vec3 position) {
  const glm::vec3 margin = (box.max - box.min) * 0.1f + glm::vec3(0.01f);
  return glm::all(glm::greaterThanEqual(position, box.min - margin)) && glm::all(glm::lessThanEqual(position, box.max + margin));
}

bool glows(const assets::Material& material) {
  return material.emissive_strength > 0.0f && glm::any(glm::greaterThan(material.emissive_factor, glm::vec3(0.0f)));
}

// The batch state of a caster: depth-only passes need textures only for the
// alpha test, and draw both faces so that open geometry (a single-sided wall
// seen from behind) still blocks light.
auto caster_key(const render::DrawBatch& b) { return std::tie(b.alpha_masked, b.vertex_array, b.textures, b.samplers); }

// Sends the patched lights of the staging copy to the GPU: runs of indices
// less than kGap apart go as one upload (the lights between are unchanged, so
// resending them is harmless), which keeps K shadowed lights from costing K
// calls without resending a million lights for two far apart.
void upload_patched_lights(render::LightBuffer& lights, std::vector<std::uint32_t>& patched) {
  constexpr std::uint32_t kGap = 64;
  if (!patched.empty()) ++lights.sends;
  std::sort(patched.begin(), patched.end());
  for (std::size_t begin = 0; begin < patched.size();) {
    std::size_t end = begin + 1;
    while (end < patched.size() && patched[end] - patched[end - 1] < kGap) ++end;
    const std::uint32_t first = patched[begin], last = patched[end - 1];
    glNamedBufferSubData(lights.buffer.id(), static_cast<GLintptr>(first * sizeof(render::GpuLight)),
                         static_cast<GLsizeiptr>((last - first + 1) * sizeof(render::GpuLight)), &lights.staging[first]);
    begin = end;
  }
}

// Moves the chosen lights to the front of the frame's lights, swapping each
// one found further back with an unchosen light at the front, and records the
// indices that changed in `moved`. Light loops then take the shadowed lights
// first, with the map lookup, and the rest without it (common/shading.glsl):
// a lookup in one loop body would cost every light on a GPU's divergent lanes
// and on llvmpipe, which runs both sides of a branch.
void move_to_front(render::LightBuffer& lights, std::vector<ShadowChoice>& choices, std::vector<std::uint32_t>& moved) {
  const auto front = static_cast<std::uint32_t>(choices.size());
  std::vector<bool> taken(front, false);
  for (const ShadowChoice& c : choices) {
    if (c.light < front) taken[c.light] = true;
  }
  std::uint32_t free = 0;
  for (ShadowChoice& c : choices) {
    if (c.light < front) continue;
    while (taken[free]) ++free;
    std::swap(lights.staging[free], lights.staging[c.light]);
    std::swap(lights.entities[free], lights.entities[c.light]);
    moved.push_back(free);
    moved.push_back(c.light);
    c.light = free;
    taken[free] = true;
  }
}

}  // namespace

ShadowAtlas::ShadowAtlas(render::GpuAssets& gpu) : gpu_(gpu), allocator_(limits_.max_tile, limits_.min_tile) {}

void ShadowAtlas::release() {
  entries_.clear();
  views_.clear();
  boxes_.clear();
  atlas_ = {};
  framebuffer_ = {};
  view_buffer_ = {};
  instances_ = {};
  materials_ = {};
  commands_ = {};
}

void ShadowAtlas::ensure_atlas() {
  if (atlas_) return;
  const int size = static_cast<int>(std::bit_floor(static_cast<unsigned>(std::min(kAtlasSize, gfx::max_texture_size()))));
  limits_.atlas_size = size;
  limits_.max_tile = std::min(limits_.max_tile, size);
  allocator_ = AtlasAllocator(size, limits_.min_tile);
  atlas_ = gfx::create_texture(GL_TEXTURE_2D);
  glTextureStorage2D(atlas_.id(), 1, kAtlasFormat, size, size);
  // Hardware comparison with bilinear filtering: each tap is a 2x2 PCF.
  glTextureParameteri(atlas_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(atlas_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(atlas_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(atlas_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTextureParameteri(atlas_.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  // Lit where the surface is at least as close to the light as the map's nearest caster.
  glTextureParameteri(atlas_.id(), GL_TEXTURE_COMPARE_FUNC, gfx::kDepthCloserOrEqual);
  framebuffer_ = gfx::create_framebuffer();
  glNamedFramebufferTexture(framebuffer_.id(), GL_DEPTH_ATTACHMENT, atlas_.id(), 0);
  glNamedFramebufferDrawBuffer(framebuffer_.id(), GL_NONE);
  gfx::require_complete(framebuffer_.id(), "shadow atlas");
  const float far = gfx::kDepthFar;
  glClearNamedFramebufferfv(framebuffer_.id(), GL_DEPTH, 0, &far);
}

void ShadowAtlas::collect_changed_geometry(ecs::Registry& registry) {
  changed_.clear();
  ++frame_;
  registry.view<WorldBounds>().each([&](ecs::Entity entity, const WorldBounds& bounds) {
    const Box& box = bounds;
    auto [it, added] = boxes_.try_emplace(entity, Seen{box, frame_});
    if (added) {
      if (!box.empty) changed_.push_back(box);
    } else {
      if (it->second.box != box) {
        if (!it->second.box.empty) changed_.push_back(it->second.box);
        if (!box.empty) changed_.push_back(box);
        it->second.box = box;
      }
      it->second.frame = frame_;
    }
  });
  for (auto it = boxes_.begin(); it != boxes_.end();) {
    if (it->second.frame == frame_) {
      ++it;
      continue;
    }
    if (!it->second.box.empty) changed_.push_back(it->second.box);
    it = boxes_.erase(it);
  }
}

void ShadowAtlas::gather_casters(ecs::Registry& registry) {
  casters_.clear();
  caster_states_.clear();
  caster_instances_.clear();
  caster_materials_.clear();
  const auto& assets = registry.resource<assets::AssetManager>();
  std::map<const assets::Material*, std::uint32_t> material_index;
  std::vector<render::DrawBatch> states;  // distinct caster states, in order of first use
  registry.view<Transform, MeshInstance, WorldBounds>().each([&](const Transform&, const MeshInstance& instance, const WorldBounds& bounds) {
    if (bounds.empty || bounds.asset != instance.asset || bounds.mesh != instance.mesh) return;
    const assets::MeshAsset& asset = assets.mesh_asset(instance.asset);
    if (instance.mesh >= asset.meshes.size()) return;
    const render::GpuMeshAsset& gpu_asset = gpu_.mesh_asset(instance.asset);
    const auto& primitives = asset.meshes[instance.mesh].primitives;
    bool used = false;
    render::InstanceData data;
    data.model = bounds.model;
    for (std::uint32_t p = 0; p < primitives.size() && p < bounds.primitives.size(); ++p) {
      const assets::Primitive& primitive = primitives[p];
      if (primitive.indices.empty() || bounds.primitives[p].empty) continue;
      const assets::Material& material = asset.materials.at(primitive.material);
      // Blended surfaces cast no shadow (glass lets light through).
      if (material.alpha_mode == assets::AlphaMode::Blend) continue;
      render::DrawBatch state = render::batch_state(material, gpu_, gpu_.vertex_array(), false);
      state.double_sided = true;
      std::uint32_t material_slot = 0;
      if (!state.alpha_masked) {
        state.textures = {};
        state.samplers = {};
      } else {
        const auto [it, added] = material_index.try_emplace(&material, static_cast<std::uint32_t>(caster_materials_.size()));
        if (added) caster_materials_.push_back(render::material_data(material, gpu_));
        material_slot = it->second;
      }
      // Casters share a material record only through the instance, so a masked
      // primitive needs an instance record of its own material.
      if (!used || material_slot != caster_instances_.back().material.x) {
        data.material.x = material_slot;
        caster_instances_.push_back(data);
        used = true;
      }
      auto found = std::find_if(states.begin(), states.end(), [&](const render::DrawBatch& s) { return caster_key(s) == caster_key(state); });
      if (found == states.end()) {
        states.push_back(state);
        found = states.end() - 1;
      }
      const render::GpuPrimitive& range = gpu_asset.meshes[instance.mesh][p];
      Caster caster{bounds.primitives[p], static_cast<std::uint32_t>(found - states.begin()),
                    {range.index_count, 1, range.first_index, range.base_vertex, static_cast<std::uint32_t>(caster_instances_.size() - 1)}};
      caster.glows = glows(material);
      if (!primitive.meshlets.empty() && p + 1 < bounds.meshlet_offsets.size() &&
          bounds.meshlet_offsets[p + 1] - bounds.meshlet_offsets[p] == primitive.meshlets.size()) {
        caster.meshlet_bounds = bounds.meshlets.data() + bounds.meshlet_offsets[p];
        caster.meshlets = primitive.meshlets.data();
        caster.meshlet_count = static_cast<std::uint32_t>(primitive.meshlets.size());
      }
      casters_.push_back(caster);
    }
  });
  // Number the states so that masked ones come last (draw_depth's order).
  std::vector<std::uint32_t> order(states.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return caster_key(states[a]) < caster_key(states[b]); });
  std::vector<std::uint32_t> rank(states.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) {
    rank[order[i]] = i;
    caster_states_.push_back(states[order[i]]);
  }
  for (Caster& caster : casters_) caster.state = rank[caster.state];
  if (caster_materials_.empty()) caster_materials_.emplace_back();
}

bool ShadowAtlas::update(ecs::Registry& registry, render::LightBuffer& lights, const ViewState& view, glm::ivec2 viewport, int count,
                         bool redraw) {
  stats_ = {};
  pending_views_.clear();
  pending_reach_.clear();
  if (count <= 0) {
    if (atlas_) release();
    bind();
    return false;
  }
  ensure_atlas();
  stats_.atlas_size = limits_.atlas_size;
  collect_changed_geometry(registry);

  // A camera cut forgets which lights had maps: there is no flicker to
  // prevent, and the last view's choice says little about this one's.
  PreviousShadows previous;
  if (!view.cut) {
    for (const auto& [entity, entry] : entries_) previous.emplace(entity, entry.resolution);
  }
  std::vector<ShadowChoice> choices = choose_shadowed_lights(lights.staging, lights.entities, view, viewport, count, previous, limits_);

  // Lights no longer shadowed, or at another size, give their tiles back.
  std::unordered_map<ecs::Entity, const ShadowChoice*> chosen;
  for (const ShadowChoice& c : choices) chosen.emplace(c.entity, &c);
  for (auto it = entries_.begin(); it != entries_.end();) {
    const auto found = chosen.find(it->first);
    if (found != chosen.end() && found->second->resolution == it->second.resolution) {
      ++it;
      continue;
    }
    for (const AtlasTile& tile : it->second.tiles) allocator_.release(tile);
    it = entries_.erase(it);
  }
  // Newcomers, largest first; if the free space is too broken up, every map is
  // placed again from an empty atlas (their areas fit, so they pack).
  std::vector<const ShadowChoice*> newcomers;
  for (const ShadowChoice& c : choices) {
    if (!entries_.count(c.entity)) newcomers.push_back(&c);
  }
  std::stable_sort(newcomers.begin(), newcomers.end(), [](const ShadowChoice* a, const ShadowChoice* b) { return a->resolution > b->resolution; });
  auto place = [&](const ShadowChoice& c) {
    Entry entry;
    entry.resolution = c.resolution;
    const int tiles = view_count(static_cast<render::GpuLightKind>(lights.staging[c.light].color_kind.w));
    for (int t = 0; t < tiles; ++t) {
      const auto tile = allocator_.allocate(c.resolution);
      if (!tile) {
        for (const AtlasTile& given : entry.tiles) allocator_.release(given);
        return false;
      }
      entry.tiles.push_back(*tile);
    }
    entries_[c.entity] = std::move(entry);
    return true;
  };
  bool placed = true;
  for (const ShadowChoice* c : newcomers) placed = placed && place(*c);
  if (!placed) {
    entries_.clear();
    allocator_.clear();
    std::vector<const ShadowChoice*> all;
    for (const ShadowChoice& c : choices) all.push_back(&c);
    std::stable_sort(all.begin(), all.end(), [](const ShadowChoice* a, const ShadowChoice* b) { return a->resolution > b->resolution; });
    for (const ShadowChoice* c : all) place(*c);
  }
  // Only lights with maps may lead the buffer (light loops stop at the first
  // without); the selection's areas always pack, so none is left out in practice.
  std::erase_if(choices, [&](const ShadowChoice& c) { return !entries_.count(c.entity); });
  std::vector<std::uint32_t> patched;
  move_to_front(lights, choices, patched);

  // This frame's views, and which of them must be drawn.
  views_.clear();
  std::vector<std::uint32_t>& to_draw = pending_views_;
  std::vector<glm::vec4>& reach = pending_reach_;
  CascadeFrame cascade_frame{view.view, view.projection, view.near_plane, view.far_plane, glm::vec3(-1.0f), glm::vec3(1.0f)};
  if (const auto* scene = registry.try_resource<SceneBounds>(); scene && !scene->empty) {
    cascade_frame.scene_min = scene->min;
    cascade_frame.scene_max = scene->max;
  }
  const float atlas_texels = static_cast<float>(limits_.atlas_size);
  const auto* animations = registry.try_resource<LightAnimationSettings>();
  const double time = animations ? animations->time : 0.0;
  for (const ShadowChoice& c : choices) {
    Entry& entry = entries_.at(c.entity);
    render::GpuLight& light = lights.staging[c.light];
    // A light that the GPU moves is seen from where the GPU places it this
    // frame; the record is sent back with its patch (and put back next frame).
    if (render::moves_on_gpu(light)) light.position_radius = glm::vec4(render::moved_position(light, time), light.position_radius.w);
    const auto kind = static_cast<render::GpuLightKind>(light.color_kind.w);
    std::vector<ShadowView> light_views;
    if (kind == render::GpuLightKind::Point) {
      const auto faces = point_views(light, entry.resolution);
      light_views.assign(faces.begin(), faces.end());
    } else if (kind == render::GpuLightKind::Spot) {
      light_views.push_back(spot_view(light, entry.resolution));
    } else {
      const auto cascades = cascade_views(light, cascade_frame, entry.resolution);
      light_views.assign(cascades.begin(), cascades.end());
    }
    const glm::vec4 sphere = kind == render::GpuLightKind::Directional ? glm::vec4(0.0f, 0.0f, 0.0f, -1.0f) : light.position_radius;
    bool stale = redraw || !entry.drawn || !same_light(entry.drawn_light, light) || entry.drawn_views.size() != light_views.size();
    for (std::size_t v = 0; !stale && v < light_views.size(); ++v) stale = entry.drawn_views[v] != light_views[v].view_projection;
    for (std::size_t b = 0; !stale && b < changed_.size(); ++b) {
      stale = sphere.w < 0.0f || box_meets_sphere(changed_[b], glm::vec3(sphere), sphere.w);
    }
    const auto first = static_cast<std::uint32_t>(views_.size());
    for (std::size_t v = 0; v < light_views.size(); ++v) {
      ShadowView& shadow_view = light_views[v];
      const AtlasTile& tile = entry.tiles[v];
      shadow_view.rect = glm::vec4(glm::vec2(tile.origin) / atlas_texels, glm::vec2(static_cast<float>(tile.size) / atlas_texels));
      views_.push_back(shadow_view);
      if (stale) {
        to_draw.push_back(first + static_cast<std::uint32_t>(v));
        reach.push_back(sphere);
      }
    }
    if (stale) {
      entry.drawn = true;
      entry.drawn_light = light;
      entry.drawn_views.clear();
      for (const ShadowView& v : light_views) entry.drawn_views.push_back(v.view_projection);
    }
    ++stats_.lights;
    stats_.maps_rendered += stale ? static_cast<std::uint32_t>(light_views.size()) : 0u;
    stats_.maps_reused += stale ? 0u : static_cast<std::uint32_t>(light_views.size());
    // The shaders find the light's views through spot.zw (lights.glsl).
    light.spot.z = static_cast<float>(first + 1);
    light.spot.w = static_cast<float>(light_views.size());
    patched.push_back(c.light);
  }
  upload_patched_lights(lights, patched);
  lights.patched.insert(lights.patched.end(), patched.begin(), patched.end());
  view_buffer_.upload(views_.data(), views_.size() * sizeof(ShadowView));
  if (compute_free_) {
    static_assert(sizeof(ShadowView) == render::kShadowViewTexels * sizeof(glm::vec4), "a view is 6 texels (common/shadows.glsl)");
    view_texture_.upload(std::span<const glm::vec4>(reinterpret_cast<const glm::vec4*>(views_.data()), views_.size() * render::kShadowViewTexels));
  }
  bind();
  return !to_draw.empty();
}

void ShadowAtlas::draw_pending(ecs::Registry& registry) {
  if (pending_views_.empty()) return;
  gather_casters(registry);
  draw_maps(pending_views_, pending_reach_);
  bind();
}

void ShadowAtlas::draw_maps(const std::vector<std::uint32_t>& views, std::span<const glm::vec4> reach) {
  // Per view, its casters in state order: one batch per run of a state.
  std::vector<render::DrawCommand> commands;
  std::vector<std::vector<render::DrawBatch>> batches(views.size());
  std::vector<std::uint32_t> selected;
  std::vector<std::uint32_t> near_light;
  for (std::size_t v = 0; v < views.size(); ++v) {
    const glm::vec4 sphere = reach[v];
    // The six faces of a point light share its sphere: test it once.
    if (v == 0 || sphere != reach[v - 1] || sphere.w < 0.0f) {
      near_light.clear();
      for (std::uint32_t c = 0; c < casters_.size(); ++c) {
        const Caster& caster = casters_[c];
        if (sphere.w < 0.0f) {
          near_light.push_back(c);
        } else if (box_meets_sphere(caster.box, glm::vec3(sphere), sphere.w) && !(caster.glows && inside_lamp(caster.box, glm::vec3(sphere)))) {
          near_light.push_back(c);
        }
      }
    }
    const Frustum frustum = frustum_of(views_[views[v]].view_projection);
    selected.clear();
    for (const std::uint32_t c : near_light) {
      if (intersects(frustum, casters_[c].box.min, casters_[c].box.max)) selected.push_back(c);
    }
    std::stable_sort(selected.begin(), selected.end(), [&](std::uint32_t a, std::uint32_t b) { return casters_[a].state < casters_[b].state; });
    for (const std::uint32_t c : selected) {
      const Caster& caster = casters_[c];
      auto add = [&](render::DrawCommand command) {
        if (batches[v].empty() || caster_key(batches[v].back()) != caster_key(caster_states_[caster.state])) {
          batches[v].push_back(caster_states_[caster.state]);
          batches[v].back().first_command = static_cast<std::uint32_t>(commands.size());
          batches[v].back().command_count = 0;
        }
        commands.push_back(command);
        ++batches[v].back().command_count;
        stats_.triangles += command.count / 3;
      };
      if (caster.meshlet_count == 0) {
        add(caster.command);
        continue;
      }
      // Runs of meshlets inside the view and the light's reach (both faces
      // are drawn, so no normal-cone test).
      assets::for_each_meshlet_run(
          std::span(caster.meshlets, caster.meshlet_count),
          [&](std::size_t m) {
            const MeshletBounds& bounds = caster.meshlet_bounds[m];
            return intersects(frustum, bounds.center, bounds.radius) &&
                   (sphere.w < 0.0f || glm::length(bounds.center - glm::vec3(sphere)) <= sphere.w + bounds.radius);
          },
          [&](std::uint32_t first_index, std::uint32_t index_count) {
            render::DrawCommand run = caster.command;
            run.first_index += first_index;
            run.count = index_count;
            add(run);
          });
    }
  }
  gpu_.use_identity_slots(caster_instances_.size());
  if (compute_free_) {
    // The tier's twins: records in textures, commands drawn from the CPU.
    instance_texture_.upload(render::instance_texels(caster_instances_));
    material_texture_.upload(render::material_texels(caster_materials_));
    instance_texture_.bind(render::kInstanceTextureUnit);
    material_texture_.bind(render::kMaterialTextureUnit);
  } else {
    instances_.upload(caster_instances_.data(), caster_instances_.size() * sizeof(render::InstanceData));
    materials_.upload(caster_materials_.data(), caster_materials_.size() * sizeof(render::MaterialData));
    commands_.upload(commands.data(), commands.size() * sizeof(render::DrawCommand));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, render::kInstanceStorageBinding, instances_.buffer.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, render::kMaterialStorageBinding, materials_.buffer.id());
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, commands_.buffer.id());
  }
  // The casters' commands, all of them; whoever draws next binds its own.
  const render::CommandSource source{compute_free_ ? std::span<const render::DrawCommand>(commands) : std::span<const render::DrawCommand>(), -1};

  gfx::ShaderProgram& position_only = gpu_.shaders().get({"common/mesh.vert", "common/depth_only.frag"}, {{"POSITION_ONLY"}, {"SHADOW_PASS"}});
  gfx::ShaderProgram& masked = gpu_.shaders().get({"common/mesh.vert", "common/depth_masked.frag"}, {{"SHADOW_PASS"}});
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(gfx::kDepthCloser);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glDisable(GL_STENCIL_TEST);
  glEnable(GL_SCISSOR_TEST);
  glEnable(GL_POLYGON_OFFSET_FILL);
  // Reversed Z: pushing a map's depth away from the light means towards 0.
  glPolygonOffset(-kSlopeBias, -kConstantBias);
  const float far = gfx::kDepthFar;
  const float texels = static_cast<float>(limits_.atlas_size);
  for (std::size_t v = 0; v < views.size(); ++v) {
    const ShadowView& view = views_[views[v]];
    const glm::ivec4 tile(glm::round(glm::vec4(view.rect) * texels));
    glViewport(tile.x, tile.y, tile.z, tile.w);
    glScissor(tile.x, tile.y, tile.z, tile.w);
    glClearNamedFramebufferfv(framebuffer_.id(), GL_DEPTH, 0, &far);
    if (batches[v].empty()) continue;
    position_only.set("u_shadow_view_projection", view.view_projection);
    masked.set("u_shadow_view_projection", view.view_projection);
    render::draw_depth(batches[v], source, position_only, masked);
  }
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDisable(GL_SCISSOR_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void ShadowAtlas::bind() const {
  if (compute_free_) view_texture_.bind(render::kShadowViewTextureUnit);
  else glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kShadowViewBinding, view_buffer_.buffer.id());
}

}  // namespace atrium::shadows
