// Evaluates a GLSL expression on the GPU for many inputs, so that a GLSL
// function can be compared with its C++ twin. The probe is a compute shader
// written to a temporary folder that can #include the engine's shader files;
// `expression` reads `value` (of GLSL type `input_type`) and yields the output.
#pragma once

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <unistd.h>

#include "gfx/shader_program.hpp"

namespace atrium::testing {

template <typename Out, typename In>
std::vector<Out> evaluate_glsl(const std::string& includes, const std::string& input_type, const std::string& output_type,
                               const std::string& expression, const std::vector<In>& inputs,
                               const std::function<void()>& bind_state = {}) {
  const auto folder = std::filesystem::temp_directory_path() / ("atrium_probe_" + std::to_string(::getpid()));
  std::filesystem::create_directories(folder);
  std::ofstream(folder / "probe.comp") << "#version 450 core\n"
                                          "layout(local_size_x = 64) in;\n"
                                       << includes
                                       << "layout(std430, binding = 7) readonly buffer In { " << input_type << " inputs[]; };\n"
                                       << "layout(std430, binding = 8) writeonly buffer Out { " << output_type << " outputs[]; };\n"
                                       << "uniform uint u_count;\n"
                                          "void main() {\n"
                                          "  uint i = gl_GlobalInvocationID.x;\n"
                                          "  if (i >= u_count) return;\n"
                                       << "  " << input_type << " value = inputs[i];\n"
                                       << "  outputs[i] = " << expression << ";\n"
                                       << "}\n";
  gfx::ShaderSearchPath path{folder};
  for (const auto& p : gfx::default_shader_path()) path.push_back(p);
  gfx::ShaderProgram program = gfx::ShaderProgram::load({"probe.comp"}, {}, path);
  std::filesystem::remove_all(folder);

  gfx::Buffer input = gfx::create_buffer(), output = gfx::create_buffer();
  glNamedBufferStorage(input.id(), static_cast<GLsizeiptr>(inputs.size() * sizeof(In)), inputs.data(), 0);
  glNamedBufferStorage(output.id(), static_cast<GLsizeiptr>(inputs.size() * sizeof(Out)), nullptr, 0);
  if (bind_state) bind_state();
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 7, input.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 8, output.id());
  program.set("u_count", static_cast<unsigned>(inputs.size()));
  program.use();
  glDispatchCompute(static_cast<GLuint>((inputs.size() + 63) / 64), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<Out> outputs(inputs.size());
  glGetNamedBufferSubData(output.id(), 0, static_cast<GLsizeiptr>(outputs.size() * sizeof(Out)), outputs.data());
  return outputs;
}

}  // namespace atrium::testing
