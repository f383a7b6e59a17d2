#include "gfx/glsl_dialect.hpp"

#include <algorithm>
#include <regex>
#include <stdexcept>
#include <sstream>

namespace atrium::gfx {
namespace {

// Every sampler type without a default precision in ES 3.00 (sampler2D and
// samplerCube have lowp, too little for depth and records).
constexpr const char* kEsPrecision =
    "precision highp float; precision highp int; precision highp sampler2D; precision highp sampler3D; "
    "precision highp samplerCube; precision highp sampler2DShadow; precision highp samplerCubeShadow; "
    "precision highp sampler2DArray; precision highp sampler2DArrayShadow; precision highp isampler2D; "
    "precision highp usampler2D; precision highp isampler3D; precision highp usampler3D; "
    "precision highp isampler2DArray; precision highp usampler2DArray; ";

// `layout(...)` with `binding = N` taken out of its list; the whole qualifier
// goes when nothing else is in it.
std::string without_binding(const std::string& qualifiers) {
  static const std::regex kBinding(R"(\s*,?\s*\bbinding\s*=\s*\d+\s*,?)");
  std::string rest = std::regex_replace(qualifiers, kBinding, ",");
  static const std::regex kCommas(R"(^\s*,+|,+\s*$)");
  rest = std::regex_replace(rest, kCommas, "");
  static const std::regex kDoubled(R"(\s*,\s*,\s*)");
  rest = std::regex_replace(rest, kDoubled, ", ");
  return rest.find_first_not_of(" \t,") == std::string::npos ? std::string() : "layout(" + rest + ") ";
}

// The precision statements go in front of the first line of code, on that
// line, so that no line moves and any #extension lines stay first.
std::string with_precision(const std::string& text) {
  std::istringstream lines(text);
  std::string line, out;
  bool placed = false, in_comment = false;
  while (std::getline(lines, line)) {
    if (!placed) {
      const auto first = line.find_first_not_of(" \t\r");
      const bool blank = first == std::string::npos;
      const bool directive = !blank && line[first] == '#';
      const bool comment = !blank && line.compare(first, 2, "//") == 0;
      const bool comment_opens = !blank && line.compare(first, 2, "/*") == 0;
      if (in_comment || comment_opens) {
        in_comment = line.find("*/") == std::string::npos;
      } else if (!blank && !directive && !comment) {
        line = kEsPrecision + line;
        placed = true;
      }
    }
    out += line + "\n";
  }
  return out;
}

}  // namespace

GlslDialect glsl_dialect(const GlFeatures& features) {
  GlslDialect dialect;
  if (features.es) {
    dialect.version = "300 es";
    dialect.es = true;
    dialect.stage_locations = false;
  } else {
    dialect.version = std::to_string(std::min(features.version, 45) * 10) + " core";
  }
  dialect.binding_qualifiers = features.binding_qualifiers;
  dialect.early_fragment_tests = features.binding_qualifiers;  // both came with GLSL 4.20 / ES 3.10
  return dialect;
}

DialectText to_dialect(const std::string& text, GLenum stage, const GlslDialect& dialect) {
  DialectText result{text, {}};
  if (dialect.is_native()) return result;
  std::string& out = result.text;

  static const std::regex kVersion(R"(#version\s+450\s+core)");
  out = std::regex_replace(out, kVersion, "#version " + dialect.version, std::regex_constants::format_first_only);

  if (!dialect.binding_qualifiers) {
    // layout(..., binding = N, ...) uniform [precision] TYPE NAME[[count]]  or  uniform BLOCK {
    static const std::regex kUniform(
        R"(layout\s*\(([^)]*\bbinding\s*=\s*(\d+)[^)]*)\)\s*uniform\s+(?:(?:lowp|mediump|highp)\s+)?(\w+)\s*(\{|\w+)(?:\s*\[\s*(\d+)\s*\])?)");
    std::string rewritten;
    auto begin = std::sregex_iterator(out.begin(), out.end(), kUniform);
    std::size_t copied = 0;
    for (auto it = begin; it != std::sregex_iterator(); ++it) {
      const std::smatch& m = *it;
      // Images (and their memory qualifiers) exist only where compute does;
      // the tier's defines leave them out, and they stay as written.
      static const std::regex kImage(R"(image|coherent|readonly|writeonly|volatile|restrict)");
      if (std::regex_search(m[3].str(), kImage) || std::regex_search(m[4].str(), kImage)) continue;
      const bool block = m[4].str() == "{";
      GlslBinding binding{block ? m[3].str() : m[4].str(), std::stoi(m[2].str()), m[5].matched ? std::stoi(m[5].str()) : 1, block};
      // Branches the defines leave out are still in the text, so one name
      // must keep one binding in all of them.
      const auto same = std::find_if(result.bindings.begin(), result.bindings.end(), [&](const GlslBinding& b) {
        return b.name == binding.name && b.block == binding.block;
      });
      if (same != result.bindings.end() && *same != binding) {
        throw std::invalid_argument(binding.name + " has binding " + std::to_string(same->unit) + " in one place and " +
                                    std::to_string(binding.unit) +
                                    " in another; a context without binding qualifiers needs one binding per name");
      }
      if (same == result.bindings.end()) result.bindings.push_back(binding);
      const std::string whole = m.str();
      const std::size_t layout_end = whole.find(')') + 1;
      rewritten += out.substr(copied, static_cast<std::size_t>(m.position()) - copied);
      rewritten += without_binding(m[1].str()) + whole.substr(whole.find_first_not_of(" \t", layout_end));
      copied = static_cast<std::size_t>(m.position() + m.length());
    }
    rewritten += out.substr(copied);
    out = std::move(rewritten);
  }

  if (!dialect.stage_locations) {
    // ES 3.00 takes a location on a vertex shader's inputs and a fragment
    // shader's outputs only. What a stage passes on may be declared through a
    // macro (common/mesh_interface.glsl's MESH_VARYING), so every other
    // location goes, whatever word follows its interpolation qualifiers.
    const std::string kept = stage == GL_VERTEX_SHADER ? "in" : stage == GL_FRAGMENT_SHADER ? "out" : "";
    if (!kept.empty()) {
      const std::regex kLocation(R"re(layout\s*\(\s*location\s*=\s*\d+\s*\)(?!\s*(?:(?:flat|smooth|centroid)\s+)*)re" + kept +
                                 R"re(\b)\s*)re");
      out = std::regex_replace(out, kLocation, "");
    }
  }

  if (!dialect.early_fragment_tests) {
    static const std::regex kEarly(R"(layout\s*\(\s*early_fragment_tests\s*\)\s*in\s*;)");
    out = std::regex_replace(out, kEarly, "");
  }

  if (dialect.es) out = with_precision(out);
  return result;
}

void apply_bindings(GLuint program, const std::vector<GlslBinding>& bindings) {
  for (const GlslBinding& binding : bindings) {
    if (binding.block) {
      const GLuint index = glGetUniformBlockIndex(program, binding.name.c_str());
      if (index != GL_INVALID_INDEX) glUniformBlockBinding(program, index, static_cast<GLuint>(binding.unit));
      continue;
    }
    const GLint location = glGetUniformLocation(program, binding.name.c_str());
    if (location < 0) continue;
    std::vector<GLint> units(static_cast<std::size_t>(binding.count));
    for (int i = 0; i < binding.count; ++i) units[static_cast<std::size_t>(i)] = binding.unit + i;
    glProgramUniform1iv(program, location, binding.count, units.data());
  }
}

}  // namespace atrium::gfx
