#include "systems/lighting/light_volumes.hpp"

#include <algorithm>
#include <map>

#include "gfx/depth.hpp"

namespace atrium::lighting {
namespace {

struct SphereMesh {
  std::vector<glm::vec3> vertices;
  std::vector<std::uint32_t> indices;
  float circumscribe = 1.0f;
};

// An icosahedron subdivided twice (320 faces), vertices on the unit sphere.
// `circumscribe` is 1 / the smallest distance from the centre to a face, so the
// scaled mesh contains the whole true sphere.
SphereMesh make_sphere() {
  const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
  SphereMesh mesh;
  for (const glm::vec3 v : {glm::vec3(-1, t, 0), glm::vec3(1, t, 0), glm::vec3(-1, -t, 0), glm::vec3(1, -t, 0),
                            glm::vec3(0, -1, t), glm::vec3(0, 1, t), glm::vec3(0, -1, -t), glm::vec3(0, 1, -t),
                            glm::vec3(t, 0, -1), glm::vec3(t, 0, 1), glm::vec3(-t, 0, -1), glm::vec3(-t, 0, 1)}) {
    mesh.vertices.push_back(glm::normalize(v));
  }
  mesh.indices = {0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4, 11, 10, 2, 10, 7, 6, 7, 1, 8,
                  3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8, 3, 8, 9, 4, 9, 5, 2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1};
  for (int level = 0; level < 2; ++level) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::minmax(a, b);
      auto it = midpoints.find(key);
      if (it != midpoints.end()) return it->second;
      mesh.vertices.push_back(glm::normalize(mesh.vertices[a] + mesh.vertices[b]));
      return midpoints[key] = static_cast<std::uint32_t>(mesh.vertices.size() - 1);
    };
    std::vector<std::uint32_t> finer;
    for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
      const std::uint32_t a = mesh.indices[i], b = mesh.indices[i + 1], c = mesh.indices[i + 2];
      const std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      finer.insert(finer.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
    }
    mesh.indices = std::move(finer);
  }
  float nearest = 1.0f;
  for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
    const glm::vec3 a = mesh.vertices[mesh.indices[i]], b = mesh.vertices[mesh.indices[i + 1]], c = mesh.vertices[mesh.indices[i + 2]];
    nearest = std::min(nearest, std::abs(glm::dot(glm::normalize(glm::cross(b - a, c - a)), a)));
  }
  mesh.circumscribe = 1.0f / nearest;
  return mesh;
}

}  // namespace

LightVolumeTechnique::LightVolumeTechnique(assets::GpuAssets& gpu, const TechniqueOptions& options, bool instanced)
    : instanced_(instanced),
      geometry_(gpu.shaders().get({"common/mesh.vert", "deferred/geometry.frag"})),
      unlit_(gpu.shaders().get({"post/fullscreen.vert", "light_volumes/unlit.frag"})),
      directional_(gpu.shaders().get({"post/fullscreen.vert", "light_volumes/lighting.frag"}, {{"DIRECTIONAL_ONLY"}})),
      stencil_(gpu.shaders().get({"light_volumes/volume.vert", "light_volumes/stencil.frag"})),
      lighting_(gpu.shaders().get({"light_volumes/volume.vert", "light_volumes/lighting.frag"})),
      forward_(gpu.shaders().get({"common/mesh.vert", "forward/shade.frag"})),
      gbuffer_(options.gbuffer_layout),
      sphere_vertices_(gfx::create_buffer()),
      sphere_indices_(gfx::create_buffer()),
      sphere_(gfx::create_vertex_array()) {
  const SphereMesh mesh = make_sphere();
  circumscribe_ = mesh.circumscribe;
  sphere_index_count_ = static_cast<GLsizei>(mesh.indices.size());
  glNamedBufferStorage(sphere_vertices_.id(), static_cast<GLsizeiptr>(mesh.vertices.size() * sizeof(glm::vec3)), mesh.vertices.data(), 0);
  glNamedBufferStorage(sphere_indices_.id(), static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(std::uint32_t)), mesh.indices.data(), 0);
  glVertexArrayVertexBuffer(sphere_.id(), 0, sphere_vertices_.id(), 0, sizeof(glm::vec3));
  glVertexArrayElementBuffer(sphere_.id(), sphere_indices_.id());
  glEnableVertexArrayAttrib(sphere_.id(), 0);
  glVertexArrayAttribFormat(sphere_.id(), 0, 3, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(sphere_.id(), 0, 0);
  for (gfx::ShaderProgram* program : {&stencil_, &lighting_}) program->set("u_circumscribe", circumscribe_);
}

void LightVolumeTechnique::resize(const FrameTargets& targets) { gbuffer_.resize(targets.size, targets.depth_stencil); }

void LightVolumeTechnique::execute(const FrameContext& frame, const FrameTargets& targets) {
  gbuffer_.draw_geometry(geometry_, frame);
  {
    const auto pass = frame.timer.scope("base");
    gbuffer_.draw_fullscreen(unlit_, targets);
  }
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  const bool any_directional = std::any_of(frame.lights.begin(), frame.lights.end(), [](const GpuLight& light) {
    return light.color_kind.w == static_cast<float>(GpuLightKind::Directional);
  });
  if (any_directional) {
    const auto pass = frame.timer.scope("directional");
    gbuffer_.draw_fullscreen(directional_, targets);
  }
  {
    // Stencil and lighting alternate per light, so they are timed together.
    const auto pass = frame.timer.scope(instanced_ ? "volumes" : "volumes (stencil + lighting)");
    glEnable(GL_DEPTH_CLAMP);
    glBindVertexArray(sphere_.id());
    if (instanced_) draw_volumes_instanced(frame);
    else draw_volumes_with_stencil(frame);
    glBindVertexArray(0);
  }
  glDisable(GL_DEPTH_CLAMP);
  glDisable(GL_BLEND);
  glDisable(GL_STENCIL_TEST);
  glCullFace(GL_BACK);
  glDepthFunc(gfx::kDepthCloser);
  glDepthMask(GL_TRUE);

  draw_transparent(forward_, frame, targets);
}

void LightVolumeTechnique::draw_volumes_with_stencil(const FrameContext& frame) {
  glEnable(GL_STENCIL_TEST);
  glDepthMask(GL_FALSE);
  glClear(GL_STENCIL_BUFFER_BIT);
  for (std::size_t i = 0; i < frame.lights.size(); ++i) {
    if (frame.lights[i].color_kind.w == static_cast<float>(GpuLightKind::Directional)) continue;
    const auto index = static_cast<unsigned>(i);
    // Stencil: no colour, depth test on, both faces; z-fail counting.
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(gfx::kDepthCloser);
    glDisable(GL_CULL_FACE);
    glStencilFunc(GL_ALWAYS, 0, 0xff);
    glStencilOpSeparate(GL_BACK, GL_KEEP, GL_INCR_WRAP, GL_KEEP);
    glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_DECR_WRAP, GL_KEEP);
    stencil_.set("u_light_index", index);
    stencil_.set("u_instanced", 0);
    stencil_.use();
    glDrawElements(GL_TRIANGLES, sphere_index_count_, GL_UNSIGNED_INT, nullptr);
    // Lighting: back faces cover the volume's whole footprint; shade where the
    // stencil is non-zero and reset it there for the next light.
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT);
    glStencilFunc(GL_NOTEQUAL, 0, 0xff);
    glStencilOp(GL_KEEP, GL_ZERO, GL_ZERO);
    lighting_.set("u_light_index", index);
    lighting_.set("u_instanced", 0);
    lighting_.use();
    glDrawElements(GL_TRIANGLES, sphere_index_count_, GL_UNSIGNED_INT, nullptr);
  }
}

void LightVolumeTechnique::draw_volumes_instanced(const FrameContext& frame) {
  if (frame.lights.empty()) return;
  // Back faces at or behind the scene's depth: the surface is in front of the
  // sphere's far side, which includes every pixel inside the sphere.
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(gfx::kDepthFartherOrEqual);
  glDepthMask(GL_FALSE);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_FRONT);
  lighting_.set("u_instanced", 1);
  lighting_.use();
  glDrawElementsInstanced(GL_TRIANGLES, sphere_index_count_, GL_UNSIGNED_INT, nullptr, static_cast<GLsizei>(frame.lights.size()));
}

}  // namespace atrium::lighting
