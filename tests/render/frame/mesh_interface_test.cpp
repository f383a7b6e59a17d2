// common/mesh_interface.glsl, the values common/mesh.vert hands the fragment
// shader of every mesh pass: in each program the frame compiles with mesh.vert
// (every mode, with and without MSAA, shadow maps included), every value the
// fragment stage reads sits at the location where the vertex stage writes it,
// and that location is the file's, not one a linker chose. Each stage is
// compiled on its own (a separable program) to ask where it puts them: on the
// H200 a masked geometry pass whose stages declared their values in different
// orders read float bits as its triangle identifier.
#include <map>
#include <string>

#include "app/world.hpp"
#include "gfx/shader_program.hpp"
#include "render/gpu_assets.hpp"
#include "render/techniques/technique.hpp"
#include "support/gl_test.hpp"

namespace atrium {
namespace {

using MeshInterface = testing::GlTest;

// Name -> location of what `file`, compiled alone with `defines`, passes on
// (GL_PROGRAM_OUTPUT of a vertex stage) or takes in (GL_PROGRAM_INPUT of a
// fragment stage); built-ins left out.
std::map<std::string, GLint> stage_values(GLenum stage, const std::string& file, const std::vector<gfx::ShaderDefine>& defines) {
  const std::string text = gfx::preprocess_shader(gfx::default_shader_path(), file, defines).text;
  const char* source = text.c_str();
  const GLuint program = glCreateShaderProgramv(stage, 1, &source);
  GLint linked = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &linked);
  std::map<std::string, GLint> values;
  EXPECT_EQ(linked, GL_TRUE) << file << " does not compile alone";
  const GLenum interface = stage == GL_VERTEX_SHADER ? GL_PROGRAM_OUTPUT : GL_PROGRAM_INPUT;
  GLint count = 0;
  glGetProgramInterfaceiv(program, interface, GL_ACTIVE_RESOURCES, &count);
  for (GLint i = 0; i < count; ++i) {
    char name[128] = {};
    glGetProgramResourceName(program, interface, static_cast<GLuint>(i), sizeof(name), nullptr, name);
    const GLenum property = GL_LOCATION;
    GLint location = -1;
    glGetProgramResourceiv(program, interface, static_cast<GLuint>(i), 1, &property, 1, nullptr, &location);
    if (!std::string(name).starts_with("gl_")) values[name] = location;
  }
  glDeleteProgram(program);
  return values;
}

std::string define_list(const std::vector<gfx::ShaderDefine>& defines) {
  std::string out;
  for (const gfx::ShaderDefine& d : defines) out += (out.empty() ? "" : " ") + d.name;
  return out;
}

TEST_F(MeshInterface, EveryMeshPassReadsEachValueWhereTheVertexStageWritesIt) {
  std::size_t pairs = 0, values = 0;
  for (const int samples : {1, 4}) {
    WorldOptions options{.lights = 16u, .mode = "forward", .size = testing::kSize};
    options.shadows = 2;
    options.technique_options.msaa = samples;
    World world(options);
    for (const std::string& mode : techniques::mode_names(options.technique_options)) {
      world.set_mode(mode);
      world.frame(0.0);
    }
    world.registry().resource<render::GpuAssets>().shaders().for_each(
        [&](const std::vector<std::string>& files, const std::vector<gfx::ShaderDefine>& defines, const gfx::ShaderProgram&) {
          if (files.size() != 2 || files[0] != "common/mesh.vert") return;
          ++pairs;
          const std::string program = files[1] + " [" + define_list(defines) + "]";
          const std::map<std::string, GLint> written = stage_values(GL_VERTEX_SHADER, files[0], defines);
          for (const auto& [name, location] : stage_values(GL_FRAGMENT_SHADER, files[1], defines)) {
            ++values;
            const auto it = written.find(name);
            if (it == written.end()) {
              ADD_FAILURE() << program << " reads " << name << ", which mesh.vert does not write";
              continue;
            }
            EXPECT_GE(location, 0) << program << ": " << name << " has no location of its own (common/mesh_interface.glsl gives one)";
            EXPECT_EQ(location, it->second) << program << ": " << name << " is read at another location than mesh.vert writes it";
          }
        });
  }
  EXPECT_GE(pairs, 20u) << "every mode's mesh passes, twice";
  EXPECT_GE(values, 100u);
}

}  // namespace
}  // namespace atrium
