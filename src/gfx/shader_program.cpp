#include "gfx/shader_program.hpp"

#include <algorithm>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string_view>

#include <glm/gtc/type_ptr.hpp>

#include "gfx/gl_features.hpp"
#include "gfx/glsl_dialect.hpp"

namespace atrium::gfx {
namespace fs = std::filesystem;

ShaderSearchPath default_shader_path() {
  if (const char* dir = std::getenv("ATRIUM_SHADER_DIR"); dir && *dir) return {dir};
  return {ATRIUM_SHADER_DIR};
}

namespace {

// The directive a line opens with (`if`, `ifdef`, `include`, ...), a view
// into `line`, or empty.
std::string_view directive(std::string_view line) {
  std::size_t at = line.find_first_not_of(" \t");
  if (at == std::string_view::npos || line[at] != '#') return {};
  at = line.find_first_not_of(" \t", at + 1);
  if (at == std::string_view::npos) return {};
  line.remove_prefix(at);
  return line.substr(0, line.find_first_not_of("abcdefghijklmnopqrstuvwxyz"));
}

// The quoted name of an `#include "name"` line, or nullopt for any other line.
std::optional<std::string> include_target(std::string_view line) {
  const std::string_view name = directive(line);
  if (name != "include") return std::nullopt;
  line.remove_prefix(static_cast<std::size_t>(name.data() - line.data()) + name.size());
  line.remove_prefix(std::min(line.find_first_not_of(" \t"), line.size()));
  if (!line.starts_with('"')) return std::nullopt;
  const auto close = line.find('"', 1);
  if (close == std::string_view::npos) return std::nullopt;
  const std::string_view rest = line.substr(close + 1);
  if (rest.find_first_not_of(" \t\r") != std::string_view::npos) return std::nullopt;
  return std::string(line.substr(1, close - 1));
}

// Parses the leading digits of `text`, advancing it; nullopt when there are none.
std::optional<unsigned long> take_number(std::string_view& text) {
  std::size_t digits = 0;
  while (digits < text.size() && text[digits] >= '0' && text[digits] <= '9') ++digits;
  if (digits == 0 || digits > 9) return std::nullopt;
  const unsigned long value = std::stoul(std::string(text.substr(0, digits)));
  text.remove_prefix(digits);
  return value;
}

struct LogLocation {
  unsigned long source = 0;
  unsigned long line = 0;
  std::string_view message;
};

// Mesa: "0:12(5): error: msg"; NVIDIA: "0(12) : error C0000: msg".
std::optional<LogLocation> parse_log_location(std::string_view text) {
  LogLocation location;
  const auto source = take_number(text);
  if (!source) return std::nullopt;
  location.source = *source;
  if (text.starts_with(':')) {
    text.remove_prefix(1);
    const auto line = take_number(text);
    if (!line || !text.starts_with('(')) return std::nullopt;
    location.line = *line;
    text.remove_prefix(text.find(')') == std::string_view::npos ? text.size() : text.find(')') + 1);
  } else if (text.starts_with('(')) {
    text.remove_prefix(1);
    const auto line = take_number(text);
    if (!line || !text.starts_with(')')) return std::nullopt;
    location.line = *line;
    text.remove_prefix(1);
  } else {
    return std::nullopt;
  }
  while (text.starts_with(' ')) text.remove_prefix(1);
  if (!text.starts_with(':')) return std::nullopt;
  text.remove_prefix(1);
  while (text.starts_with(' ')) text.remove_prefix(1);
  location.message = text;
  return location;
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

// Files are pasted in where they are first included and left out after (the
// GLSL preprocessor, which runs later, has no #pragma once). So a file first
// included inside a conditional block is missing wherever that block compiled
// out: a later #include outside the block is refused, naming both lines.
struct Preprocessor {
  const ShaderSearchPath& path;
  PreprocessedShader result;
  // The conditional blocks (#if..., each #elif and #else a block of its own)
  // open at the current line, across the files being pasted, by number.
  std::vector<int> blocks;
  int next_block = 0;
  // Each file pasted in, with the blocks open where it was first included
  // (none for the stage's main file).
  struct FirstInclude {
    std::vector<int> blocks;
    std::string where;  // "file:line"
  };
  std::map<std::string, FirstInclude> included;

  void track_conditionals(std::string_view line) {
    const std::string_view name = directive(line);
    if (name == "if" || name == "ifdef" || name == "ifndef") {
      blocks.push_back(next_block++);
    } else if (name == "elif" || name == "else") {
      if (!blocks.empty()) blocks.back() = next_block++;
    } else if (name == "endif") {
      if (!blocks.empty()) blocks.pop_back();
    }
  }

  // Throws where `target`, included already, was first included inside a block this line is not in.
  void check_included_here(const std::string& target, const std::string& where) const {
    const auto first = included.find(target);
    if (first == included.end()) return;
    const std::vector<int>& outer = first->second.blocks;
    if (outer.size() <= blocks.size() && std::equal(outer.begin(), outer.end(), blocks.begin())) return;
    throw ShaderError(where + ": error: \"" + target + "\" is first included inside a conditional block (" + first->second.where +
                      "), and a file is included once: where that block compiles out it is missing here too; include it "
                      "before the block");
  }

  // Appends `name` (a root-relative path) to result.text. `defines` is non-null for
  // the stage's main file only: they go right after its #version line.
  void append(const std::string& name, const std::vector<ShaderDefine>* defines) {
    const auto source_index = static_cast<int>(result.files.size());
    result.files.push_back(name);
    included.try_emplace(name);
    const std::optional<fs::path> found = find(name);
    if (!found) throw ShaderError(name + ": cannot open shader file (looked in " + describe_path() + ")");
    const std::string text = read_text(*found);
    if (!defines) result.text += "#line 1 " + std::to_string(source_index) + "\n";
    std::istringstream lines(text);
    std::string line;
    int line_number = 0;
    while (std::getline(lines, line)) {
      ++line_number;
      if (const auto included_name = include_target(line)) {
        const std::string target = resolve(name, *included_name, line_number);
        const std::string where = name + ":" + std::to_string(line_number);
        if (!included.contains(target)) {
          included[target] = {blocks, where};
          append(target, nullptr);
          result.text += "#line " + std::to_string(line_number + 1) + " " + std::to_string(source_index) + "\n";
        } else {
          check_included_here(target, where);
          result.text += "\n";
        }
        continue;
      }
      track_conditionals(line);
      result.text += line + "\n";
      if (defines && line.rfind("#version", 0) == 0) {
        for (const auto& define : *defines) result.text += "#define " + define.name + " " + define.value + "\n";
        result.text += "#line " + std::to_string(line_number + 1) + " " + std::to_string(source_index) + "\n";
        defines = nullptr;
      }
    }
    if (defines) throw ShaderError(name + ":1: error: the main shader file must start with #version");
  }

  std::optional<fs::path> find(const std::string& name) const {
    for (const fs::path& folder : path) {
      if (fs::is_regular_file(folder / name)) return folder / name;
    }
    return std::nullopt;
  }

  std::string describe_path() const {
    std::string out;
    for (const fs::path& folder : path) out += (out.empty() ? "" : ", ") + folder.string();
    return out;
  }

  std::string resolve(const std::string& from, const std::string& target, int line_number) const {
    const std::string beside = (fs::path(from).parent_path() / target).lexically_normal().generic_string();
    if (find(beside)) return beside;
    const std::string from_root = fs::path(target).lexically_normal().generic_string();
    if (find(from_root)) return from_root;
    throw ShaderError(from + ":" + std::to_string(line_number) + ": error: cannot find included file \"" + target + "\"");
  }
};

GLenum stage_of(const std::string& file) {
  const std::string ext = fs::path(file).extension().string();
  if (ext == ".vert") return GL_VERTEX_SHADER;
  if (ext == ".frag") return GL_FRAGMENT_SHADER;
  if (ext == ".comp") return GL_COMPUTE_SHADER;
  if (ext == ".geom") return GL_GEOMETRY_SHADER;
  throw ShaderError(file + ": unknown shader stage (expected .vert, .frag, .comp or .geom)");
}

std::string info_log(GLuint object, bool is_program) {
  GLint length = 0;
  if (is_program) glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
  else glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
  if (is_program) glGetProgramInfoLog(object, length, nullptr, log.data());
  else glGetShaderInfoLog(object, length, nullptr, log.data());
  log.resize(std::char_traits<char>::length(log.c_str()));
  return log;
}

// `defines` and what the context itself asks of every program (gfx/gl_features.hpp).
std::vector<ShaderDefine> context_defines(const std::vector<ShaderDefine>& defines) {
  std::vector<ShaderDefine> all = defines;
  const GlFeatures& features = gl_features();
  if (!features.clip_control) all.push_back({"CLIP_Z_MINUS_ONE_TO_ONE"});
  if (!features.depth_clamp) all.push_back({"NO_DEPTH_CLAMP"});
  return all;
}

}  // namespace

PreprocessedShader preprocess_shader(const ShaderSearchPath& path, const std::string& file,
                                     const std::vector<ShaderDefine>& defines) {
  Preprocessor preprocessor{path, {}, {}, 0, {}};
  preprocessor.append(fs::path(file).lexically_normal().generic_string(), &defines);
  return std::move(preprocessor.result);
}

std::string map_shader_log(const std::string& log, const std::vector<std::string>& files) {
  std::istringstream lines(log);
  std::string line;
  std::string out;
  while (std::getline(lines, line)) {
    if (line.empty()) continue;
    if (const auto at = parse_log_location(line)) {
      const std::string file = at->source < files.size() ? files[at->source] : "source " + std::to_string(at->source);
      out += file + ":" + std::to_string(at->line) + ": " + std::string(at->message) + "\n";
    } else {
      out += line + "\n";
    }
  }
  return out;
}

ShaderProgram ShaderProgram::load(const std::vector<std::string>& files, const std::vector<ShaderDefine>& defines,
                                  const ShaderSearchPath& path) {
  ShaderProgram result;
  std::vector<Shader> shaders;
  std::vector<GlslBinding> bindings;
  std::string names;
  const GlslDialect dialect = glsl_dialect(gl_features());
  const std::vector<ShaderDefine> all_defines = context_defines(defines);
  for (const auto& file : files) {
    names += (names.empty() ? "" : " + ") + file;
    const GLenum stage = stage_of(file);
    const PreprocessedShader source = preprocess_shader(path, file, all_defines);
    DialectText dialect_text;
    try {
      dialect_text = to_dialect(source.text, stage, dialect);
    } catch (const std::invalid_argument& e) {
      throw ShaderError(file + ": " + e.what());
    }
    bindings.insert(bindings.end(), dialect_text.bindings.begin(), dialect_text.bindings.end());
    Shader shader = Shader::adopt(glCreateShader(stage));
    const char* text = dialect_text.text.c_str();
    glShaderSource(shader.id(), 1, &text, nullptr);
    glCompileShader(shader.id());
    GLint ok = GL_FALSE;
    glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
    if (!ok) {
      std::string message = map_shader_log(info_log(shader.id(), false), source.files);
      if (!message.empty() && message.back() == '\n') message.pop_back();
      throw ShaderError(message.empty() ? file + ": compile failed without a log" : message);
    }
    shaders.push_back(std::move(shader));
  }
  result.program_ = Program::adopt(glCreateProgram());
  for (const auto& shader : shaders) glAttachShader(result.program_.id(), shader.id());
  glLinkProgram(result.program_.id());
  for (const auto& shader : shaders) glDetachShader(result.program_.id(), shader.id());
  GLint ok = GL_FALSE;
  glGetProgramiv(result.program_.id(), GL_LINK_STATUS, &ok);
  if (!ok) throw ShaderError(names + ": link failed: " + info_log(result.program_.id(), true));
  apply_bindings(result.program_.id(), bindings);
  if (std::any_of(files.begin(), files.end(), [](const std::string& file) { return stage_of(file) == GL_COMPUTE_SHADER; })) {
    GLint size[3] = {1, 1, 1};
    glGetProgramiv(result.program_.id(), GL_COMPUTE_WORK_GROUP_SIZE, size);
    result.work_group_size_ = glm::uvec3(size[0], size[1], size[2]);
  }
  return result;
}

void ShaderProgram::use() const { glUseProgram(program_.id()); }

GLint ShaderProgram::location(const char* name) {
  auto it = locations_.find(name);
  if (it == locations_.end()) it = locations_.emplace(name, glGetUniformLocation(program_.id(), name)).first;
  return it->second;
}

void ShaderProgram::set(const char* name, int value) { glProgramUniform1i(id(), location(name), value); }
void ShaderProgram::set(const char* name, unsigned value) { glProgramUniform1ui(id(), location(name), value); }
void ShaderProgram::set(const char* name, const glm::uvec2& v) { glProgramUniform2uiv(id(), location(name), 1, glm::value_ptr(v)); }
void ShaderProgram::set(const char* name, const glm::uvec3& v) { glProgramUniform3uiv(id(), location(name), 1, glm::value_ptr(v)); }
void ShaderProgram::set(const char* name, const glm::ivec4& v) { glProgramUniform4iv(id(), location(name), 1, glm::value_ptr(v)); }
void ShaderProgram::set(const char* name, std::span<const glm::ivec4> values) {
  glProgramUniform4iv(id(), location(name), static_cast<GLsizei>(values.size()), glm::value_ptr(values.front()));
}
void ShaderProgram::set(const char* name, float value) { glProgramUniform1f(id(), location(name), value); }
void ShaderProgram::set(const char* name, const glm::vec2& v) { glProgramUniform2fv(id(), location(name), 1, glm::value_ptr(v)); }
void ShaderProgram::set(const char* name, const glm::vec3& v) { glProgramUniform3fv(id(), location(name), 1, glm::value_ptr(v)); }
void ShaderProgram::set(const char* name, const glm::vec4& v) { glProgramUniform4fv(id(), location(name), 1, glm::value_ptr(v)); }
void ShaderProgram::set(const char* name, const glm::mat3& m) {
  glProgramUniformMatrix3fv(id(), location(name), 1, GL_FALSE, glm::value_ptr(m));
}
void ShaderProgram::set(const char* name, std::span<const glm::mat3> values) {
  glProgramUniformMatrix3fv(id(), location(name), static_cast<GLsizei>(values.size()), GL_FALSE,
                            glm::value_ptr(values.front()));
}
void ShaderProgram::set(const char* name, std::span<const int> values) {
  glProgramUniform1iv(id(), location(name), static_cast<GLsizei>(values.size()), values.data());
}
void ShaderProgram::set(const char* name, const glm::mat4& m) {
  glProgramUniformMatrix4fv(id(), location(name), 1, GL_FALSE, glm::value_ptr(m));
}

}  // namespace atrium::gfx
