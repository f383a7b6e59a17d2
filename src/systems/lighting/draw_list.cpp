#include "systems/lighting/draw_list.hpp"

#include <algorithm>
#include <map>

#include "components/mesh_instance.hpp"
#include "components/transform.hpp"
#include "gfx/depth.hpp"
#include "systems/lighting/technique.hpp"

namespace atrium::lighting {

DrawList build_draw_list(ecs::Registry& registry, const assets::AssetManager& assets, const assets::GpuAssets& gpu,
                         const glm::mat4& view) {
  DrawList list;
  // Opaque draws gather their instances per (vertex array, range, material).
  struct Key {
    GLuint vertex_array;
    std::uint32_t first_index;
    std::int32_t base_vertex;
    const assets::Material* material;
    bool mirrored;
    auto operator<=>(const Key&) const = default;
  };
  std::map<Key, std::size_t> group_of;
  std::vector<std::vector<InstanceData>> opaque_instances;
  std::vector<InstanceData> blended_instances;
  registry.view<Transform, MeshInstance>().each([&](const Transform& transform, const MeshInstance& instance) {
    const assets::MeshAsset& asset = assets.mesh_asset(instance.asset);
    const assets::GpuMeshAsset& gpu_asset = gpu.mesh_asset(instance.asset);
    if (instance.mesh >= asset.meshes.size()) return;
    InstanceData data;
    data.model = to_matrix(transform);
    data.normal_matrix = glm::mat4(glm::transpose(glm::inverse(glm::mat3(data.model))));
    const bool mirrored = glm::determinant(glm::mat3(data.model)) < 0.0f;
    const auto& primitives = asset.meshes[instance.mesh].primitives;
    for (std::size_t p = 0; p < primitives.size(); ++p) {
      const assets::Primitive& primitive = primitives[p];
      if (primitive.indices.empty()) continue;
      DrawItem item;
      item.vertex_array = gpu_asset.vertex_array.id();
      item.range = gpu_asset.meshes[instance.mesh][p];
      item.material = &asset.materials.at(primitive.material);
      item.mirrored = mirrored;
      list.triangles += primitive.indices.size() / 3;
      if (item.material->alpha_mode == assets::AlphaMode::Blend) {
        const glm::vec3 centre = 0.5f * (primitive.bounds_min + primitive.bounds_max);
        item.view_depth = -(view * data.model * glm::vec4(centre, 1.0f)).z;
        item.first_instance = static_cast<std::uint32_t>(blended_instances.size());
        blended_instances.push_back(data);
        list.blended.push_back(item);
        continue;
      }
      const Key key{item.vertex_array, item.range.first_index, item.range.base_vertex, item.material, item.mirrored};
      const auto [it, added] = group_of.try_emplace(key, list.opaque.size());
      if (added) {
        list.opaque.push_back(item);
        opaque_instances.emplace_back();
      }
      opaque_instances[it->second].push_back(data);
    }
  });
  for (std::size_t g = 0; g < list.opaque.size(); ++g) {
    list.opaque[g].first_instance = static_cast<std::uint32_t>(list.instances.size());
    list.opaque[g].instance_count = static_cast<std::uint32_t>(opaque_instances[g].size());
    list.instances.insert(list.instances.end(), opaque_instances[g].begin(), opaque_instances[g].end());
  }
  const auto blended_base = static_cast<std::uint32_t>(list.instances.size());
  list.instances.insert(list.instances.end(), blended_instances.begin(), blended_instances.end());
  for (DrawItem& item : list.blended) item.first_instance += blended_base;
  std::stable_sort(list.blended.begin(), list.blended.end(),
                   [](const DrawItem& a, const DrawItem& b) { return a.view_depth > b.view_depth; });
  return list;
}

void draw_items(gfx::ShaderProgram& program, const assets::GpuAssets& gpu, std::span<const DrawItem> items) {
  GLuint bound_vertex_array = 0;
  const assets::Material* bound_material = nullptr;
  glEnable(GL_CULL_FACE);
  for (const DrawItem& item : items) {
    if (item.vertex_array != bound_vertex_array) {
      glBindVertexArray(item.vertex_array);
      bound_vertex_array = item.vertex_array;
    }
    const assets::Material& m = *item.material;
    if (&m != bound_material) {
      bound_material = &m;
      program.set("u_base_color_factor", m.base_color_factor);
      program.set("u_metallic_factor", m.metallic_factor);
      program.set("u_roughness_factor", m.roughness_factor);
      program.set("u_emissive_factor", m.emissive_factor * m.emissive_strength);
      program.set("u_normal_scale", m.normal_scale);
      program.set("u_occlusion_strength", m.occlusion_texture.valid() ? m.occlusion_strength : 0.0f);
      program.set("u_alpha_cutoff", m.alpha_mode == assets::AlphaMode::Mask ? m.alpha_cutoff : -1.0f);
      program.set("u_has_normal_texture", m.normal_texture.valid() ? 1 : 0);
      program.set("u_normal_xy_only", gpu.two_channel(m.normal_texture.texture) ? 1 : 0);
      program.set("u_normal_green_down", m.normal_green_down ? 1 : 0);
      program.set("u_double_sided", m.double_sided ? 1 : 0);
      program.set("u_unlit", m.unlit ? 1 : 0);
      const assets::TextureSlot* slots[kMaterialTextureSlots] = {&m.base_color_texture, &m.metallic_roughness_texture,
                                                                 &m.normal_texture, &m.occlusion_texture, &m.emissive_texture};
      GLuint textures[kMaterialTextureSlots], samplers[kMaterialTextureSlots];
      glm::mat3 uv_transforms[kMaterialTextureSlots];
      int uv_sets[kMaterialTextureSlots];
      for (std::size_t s = 0; s < kMaterialTextureSlots; ++s) {
        textures[s] = gpu.texture(slots[s]->texture);
        samplers[s] = gpu.sampler(slots[s]->sampler);
        uv_transforms[s] = slots[s]->uv_transform;
        uv_sets[s] = slots[s]->uv_set;
      }
      glBindTextures(0, kMaterialTextureSlots, textures);
      glBindSamplers(0, kMaterialTextureSlots, samplers);
      program.set("u_uv_transform", std::span<const glm::mat3>(uv_transforms));
      program.set("u_uv_set", std::span<const int>(uv_sets));
      if (m.double_sided) glDisable(GL_CULL_FACE);
      else glEnable(GL_CULL_FACE);
    }
    glFrontFace(item.mirrored ? GL_CW : GL_CCW);
    glDrawElementsInstancedBaseVertexBaseInstance(
        GL_TRIANGLES, static_cast<GLsizei>(item.range.index_count), GL_UNSIGNED_INT,
        reinterpret_cast<const void*>(static_cast<std::uintptr_t>(item.range.first_index) * sizeof(std::uint32_t)),
        static_cast<GLsizei>(item.instance_count), item.range.base_vertex, item.first_instance);
  }
  glEnable(GL_CULL_FACE);
  glFrontFace(GL_CCW);
  glBindVertexArray(0);
  glBindSamplers(0, kMaterialTextureSlots, nullptr);
}

void draw_transparent(gfx::ShaderProgram& forward_program, const FrameContext& frame, const FrameTargets& targets) {
  if (frame.draws.blended.empty()) return;
  const auto pass = frame.timer.scope("transparency");
  glBindFramebuffer(GL_FRAMEBUFFER, targets.hdr_framebuffer);
  glViewport(0, 0, targets.size.x, targets.size.y);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(gfx::kDepthCloser);
  glDepthMask(GL_FALSE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  forward_program.use();
  draw_items(forward_program, frame.gpu, frame.draws.blended);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
}

void begin_scene_pass(const FrameContext& frame, const FrameTargets& targets) {
  glBindFramebuffer(GL_FRAMEBUFFER, targets.hdr_framebuffer);
  glViewport(0, 0, targets.size.x, targets.size.y);
  const float clear_color[] = {frame.background.r, frame.background.g, frame.background.b, 1.0f};
  glClearNamedFramebufferfv(targets.hdr_framebuffer, GL_COLOR, 0, clear_color);
  glClearNamedFramebufferfi(targets.hdr_framebuffer, GL_DEPTH_STENCIL, 0, gfx::kDepthFar, 0);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(gfx::kDepthCloser);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
}

void FullscreenTriangle::draw() const {
  glBindVertexArray(vertex_array_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
}

}  // namespace atrium::lighting
