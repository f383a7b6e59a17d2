// Atrium's GLSL is written once, for OpenGL 4.5 core. A context with older
// GLSL (4.1 core, ES 3.00 as on WebGL2) gets the same text with what it cannot
// parse taken out: its #version line, binding qualifiers (recorded, and set
// after linking with glUniform1i and glUniformBlockBinding), locations on
// the values passed between stages (ES 3.00 matches them by name), early
// fragment tests (the driver's own choice there), and ES's precision
// statements. The rewrite keeps every line where it was, so compile errors
// still name the right file:line.
#pragma once

#include <string>
#include <vector>

#include "gfx/gl.hpp"
#include "gfx/gl_features.hpp"

namespace atrium::gfx {

struct GlslDialect {
  std::string version = "450 core";
  bool es = false;
  bool binding_qualifiers = true;
  bool stage_locations = true;       // layout(location) on vertex outputs / fragment inputs
  bool early_fragment_tests = true;
  [[nodiscard]] bool is_native() const { return version == "450 core" && binding_qualifiers; }
};
[[nodiscard]] GlslDialect glsl_dialect(const GlFeatures& features);

// A binding qualifier taken out of the text: a sampler (`count` units from
// `unit` for an array) or a uniform block.
struct GlslBinding {
  std::string name;
  int unit = 0;
  int count = 1;
  bool block = false;
  bool operator==(const GlslBinding&) const = default;
};

struct DialectText {
  std::string text;
  std::vector<GlslBinding> bindings;
};
// `text`: a preprocessed stage (shader_program's preprocess_shader). Throws
// std::invalid_argument when one name has two bindings (in branches the
// defines choose between: the rewrite cannot tell which is compiled).
[[nodiscard]] DialectText to_dialect(const std::string& text, GLenum stage, const GlslDialect& dialect);

// Sets the recorded bindings on a linked program; names the program does not
// use (optimised out, or in a branch its defines leave out) are skipped.
void apply_bindings(GLuint program, const std::vector<GlslBinding>& bindings);

}  // namespace atrium::gfx
