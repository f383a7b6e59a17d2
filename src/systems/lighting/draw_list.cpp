#include "systems/lighting/draw_list.hpp"

#include <algorithm>

#include "components/mesh_instance.hpp"
#include "components/transform.hpp"
#include "systems/lighting/technique.hpp"

namespace atrium::lighting {

DrawList build_draw_list(ecs::Registry& registry, const assets::AssetManager& assets, const assets::GpuAssets& gpu,
                         const glm::mat4& view) {
  DrawList list;
  registry.view<Transform, MeshInstance>().each([&](const Transform& transform, const MeshInstance& instance) {
    const assets::MeshAsset& asset = assets.mesh_asset(instance.asset);
    const assets::GpuMeshAsset& gpu_asset = gpu.mesh_asset(instance.asset);
    if (instance.mesh >= asset.meshes.size()) return;
    const glm::mat4 model = to_matrix(transform);
    const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(model)));
    const auto& primitives = asset.meshes[instance.mesh].primitives;
    for (std::size_t p = 0; p < primitives.size(); ++p) {
      const assets::Primitive& primitive = primitives[p];
      DrawItem item;
      item.vertex_array = gpu_asset.vertex_array.id();
      item.range = gpu_asset.meshes[instance.mesh][p];
      item.material = &asset.materials.at(primitive.material);
      item.model = model;
      item.normal_matrix = normal_matrix;
      const glm::vec3 centre = 0.5f * (primitive.bounds_min + primitive.bounds_max);
      item.view_depth = -(view * model * glm::vec4(centre, 1.0f)).z;
      list.triangles += primitive.indices.size() / 3;
      (item.material->alpha_mode == assets::AlphaMode::Blend ? list.blended : list.opaque).push_back(item);
    }
  });
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
    program.set("u_model", item.model);
    program.set("u_normal_matrix", item.normal_matrix);
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
      program.set("u_double_sided", m.double_sided ? 1 : 0);
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
    glDrawElementsBaseVertex(GL_TRIANGLES, static_cast<GLsizei>(item.range.index_count), GL_UNSIGNED_INT,
                             reinterpret_cast<const void*>(static_cast<std::uintptr_t>(item.range.first_index) * sizeof(std::uint32_t)),
                             item.range.base_vertex);
  }
  glEnable(GL_CULL_FACE);
  glBindVertexArray(0);
  glBindSamplers(0, kMaterialTextureSlots, nullptr);
}

void draw_transparent(gfx::ShaderProgram& forward_program, const FrameContext& frame, const FrameTargets& targets) {
  if (frame.draws.blended.empty()) return;
  const auto pass = frame.timer.scope("transparency");
  glBindFramebuffer(GL_FRAMEBUFFER, targets.hdr_framebuffer);
  glViewport(0, 0, targets.size.x, targets.size.y);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
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
  glClearNamedFramebufferfi(targets.hdr_framebuffer, GL_DEPTH_STENCIL, 0, 1.0f, 0);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
}

void FullscreenTriangle::draw() const {
  glBindVertexArray(vertex_array_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
}

}  // namespace atrium::lighting
