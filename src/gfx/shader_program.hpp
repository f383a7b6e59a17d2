// GLSL programs built from files under shaders/: `#include "x"` pulls in shared
// files once each (searched beside the including file, then from each folder of
// the search path), `#define` variants are injected after `#version`, and every compile or link
// error is reported as file:line with the driver's message.
#pragma once

#include <filesystem>
#include <span>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include <glm/glm.hpp>

#include "gfx/gl_object.hpp"

namespace atrium::gfx {

class ShaderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ShaderDefine {
  std::string name;
  std::string value = "1";
  bool operator==(const ShaderDefine&) const = default;
};

// Folders searched for shader files, in order. The default holds one folder:
// $ATRIUM_SHADER_DIR, else the source tree's shaders/.
using ShaderSearchPath = std::vector<std::filesystem::path>;
[[nodiscard]] ShaderSearchPath default_shader_path();

// One stage's text after #include and #define processing. files[i] is the file
// behind GLSL source-string number i in `#line` directives and driver logs.
struct PreprocessedShader {
  std::string text;
  std::vector<std::string> files;
};
[[nodiscard]] PreprocessedShader preprocess_shader(const ShaderSearchPath& path, const std::string& file,
                                                   const std::vector<ShaderDefine>& defines);

// Rewrites driver log lines such as "0:12(5): error: ..." (Mesa) or
// "0(12) : error C1008: ..." (NVIDIA) to "common/brdf.glsl:12: error: ...".
[[nodiscard]] std::string map_shader_log(const std::string& log, const std::vector<std::string>& files);

class ShaderProgram {
 public:
  ShaderProgram() = default;
  // Stages come from the extensions .vert, .frag, .comp, .geom. Throws ShaderError.
  static ShaderProgram load(const std::vector<std::string>& files, const std::vector<ShaderDefine>& defines = {},
                            const ShaderSearchPath& path = default_shader_path());

  [[nodiscard]] GLuint id() const { return program_.id(); }
  [[nodiscard]] explicit operator bool() const { return static_cast<bool>(program_); }
  void use() const;
  // A compute program's local size (its layout, asked once at link); 1x1x1 for the other stages.
  [[nodiscard]] glm::uvec3 work_group_size() const { return work_group_size_; }

  // Uniform setters; an unknown name (optimised out) is ignored, as GL does.
  void set(const char* name, int value);
  void set(const char* name, unsigned value);
  void set(const char* name, const glm::uvec2& value);
  void set(const char* name, const glm::uvec3& value);
  void set(const char* name, const glm::ivec4& value);
  void set(const char* name, std::span<const glm::ivec4> values);
  void set(const char* name, float value);
  void set(const char* name, const glm::vec2& value);
  void set(const char* name, const glm::vec3& value);
  void set(const char* name, const glm::vec4& value);
  void set(const char* name, const glm::mat3& value);
  void set(const char* name, const glm::mat4& value);
  void set(const char* name, std::span<const glm::mat3> values);
  void set(const char* name, std::span<const int> values);

 private:
  GLint location(const char* name);

  Program program_;
  std::unordered_map<std::string, GLint> locations_;
  glm::uvec3 work_group_size_{1};
};

// Keeps the program in use across dispatches made inside a pass that draws.
// The one in use may be a deleted one (a World's, destroyed while in use):
// GL frees it once another is used, and then none is put back.
class KeepProgram {
 public:
  KeepProgram() { glGetIntegerv(GL_CURRENT_PROGRAM, &program_); }
  ~KeepProgram() { glUseProgram(program_ != 0 && glIsProgram(static_cast<GLuint>(program_)) ? static_cast<GLuint>(program_) : 0); }
  KeepProgram(const KeepProgram&) = delete;
  KeepProgram& operator=(const KeepProgram&) = delete;

 private:
  GLint program_ = 0;
};

}  // namespace atrium::gfx
