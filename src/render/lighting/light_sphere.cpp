#include "render/lighting/light_sphere.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <vector>

#include <glm/glm.hpp>

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

LightSphere::LightSphere()
    : vertices_(gfx::create_buffer()), indices_(gfx::create_index_buffer()), vertex_array_(gfx::create_vertex_array()) {
  const SphereMesh mesh = make_sphere();
  circumscribe_ = mesh.circumscribe;
  index_count_ = static_cast<GLsizei>(mesh.indices.size());
  glNamedBufferStorage(vertices_.id(), static_cast<GLsizeiptr>(mesh.vertices.size() * sizeof(glm::vec3)), mesh.vertices.data(), 0);
  glNamedBufferStorage(indices_.id(), static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(std::uint32_t)), mesh.indices.data(), 0);
  glVertexArrayVertexBuffer(vertex_array_.id(), 0, vertices_.id(), 0, sizeof(glm::vec3));
  glVertexArrayElementBuffer(vertex_array_.id(), indices_.id());
  glEnableVertexArrayAttrib(vertex_array_.id(), 0);
  glVertexArrayAttribFormat(vertex_array_.id(), 0, 3, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(vertex_array_.id(), 0, 0);
}

void LightSphere::prepare(gfx::ShaderProgram& program) const { program.set("u_circumscribe", circumscribe_); }

void LightSphere::draw(GLsizei instances) const {
  glBindVertexArray(vertex_array_.id());
  glDrawElementsInstanced(GL_TRIANGLES, index_count_, GL_UNSIGNED_INT, nullptr, instances);
}

namespace {

std::vector<gfx::ShaderDefine> shadowed(std::vector<gfx::ShaderDefine> defines) {
  defines.push_back({"SHADOWED_LIGHTS"});
  return defines;
}

}  // namespace

VolumePrograms::VolumePrograms(gfx::ShaderLibrary& shaders, const std::vector<std::string>& files,
                               std::vector<gfx::ShaderDefine> defines, int samples, const LightSphere& sphere)
    : plain_(shaders, files, defines, samples), shadowed_(shaders, files, shadowed(defines), samples) {
  each([&](gfx::ShaderProgram& program) { sphere.prepare(program); });
}

void VolumePrograms::each(const std::function<void(gfx::ShaderProgram&)>& f) const {
  plain_.each(f);
  shadowed_.each(f);
}

void VolumePrograms::draw_instanced(const LightSphere& sphere, std::uint32_t lights, std::uint32_t shadowed) const {
  // The shader's light is u_first_instance + gl_InstanceID.
  const std::uint32_t counts[] = {shadowed, lights - shadowed}, firsts[] = {0, shadowed};
  for (int set = 0; set < 2; ++set) {
    if (counts[set] == 0) continue;
    of(firsts[set], shadowed).draw([&](gfx::ShaderProgram& program) {
      program.set("u_instanced", 1);
      program.set("u_first_instance", firsts[set]);
      program.use();
      sphere.draw(static_cast<GLsizei>(counts[set]));
    });
  }
}

}  // namespace atrium::lighting
