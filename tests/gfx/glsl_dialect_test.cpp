// The GLSL rewrite for contexts older than GL 4.5 (gfx/glsl_dialect.hpp): what
// it takes out, what it records, that no line moves, and that every shader in
// the repository keeps one binding per name (what the rewrite relies on).
#include <algorithm>
#include <filesystem>

#include <gtest/gtest.h>

#include "gfx/glsl_dialect.hpp"
#include "gfx/shader_program.hpp"

namespace atrium::gfx {
namespace {
namespace fs = std::filesystem;

GlslDialect es30() {
  GlFeatures features;
  features.es = true;
  features.version = 30;
  return glsl_dialect(features);
}

GlslDialect gl41() {
  GlFeatures features;
  features.version = 41;
  features.program_uniforms = true;
  return glsl_dialect(features);
}

constexpr const char* kShader =
    "#version 450 core\n"
    "#define X 1\n"
    "/* a comment\n"
    "   over two lines */\n"
    "layout(std140, binding = 0) uniform FrameBlock {\n"
    "  mat4 m;\n"
    "};\n"
    "layout(binding = 3) uniform highp usampler2D u_lists;\n"
    "layout(binding = 4) uniform sampler2D u_textures[5];\n"
    "layout(r32ui, binding = 0) uniform coherent uimage2D u_counts;\n"
    "layout(location = 0) in vec3 a_position;\n"
    "layout(location = 1) flat out uint v_id;\n"
    "layout(early_fragment_tests) in;\n"
    "void main() {}\n";

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  for (std::size_t end; (end = text.find('\n', start)) != std::string::npos; start = end + 1) {
    lines.push_back(text.substr(start, end - start));
  }
  return lines;
}

TEST(GlslDialect, TheNativeDialectLeavesTheTextAsWritten) {
  GlFeatures features;
  features.version = 45;
  features.binding_qualifiers = true;
  const DialectText out = to_dialect(kShader, GL_VERTEX_SHADER, glsl_dialect(features));
  EXPECT_EQ(out.text, kShader);
  EXPECT_TRUE(out.bindings.empty());
}

TEST(GlslDialect, Es300TakesOutBindingsStageLocationsAndEarlyTestsAndKeepsEveryLine) {
  const DialectText out = to_dialect(kShader, GL_VERTEX_SHADER, es30());
  const std::vector<std::string> lines = lines_of(out.text);
  ASSERT_EQ(lines.size(), lines_of(kShader).size()) << out.text;
  EXPECT_EQ(lines[0], "#version 300 es");
  EXPECT_EQ(lines[1], "#define X 1");
  EXPECT_EQ(lines[2], "/* a comment") << "precision statements go after comments, never inside one";
  EXPECT_TRUE(lines[4].starts_with("precision highp float;")) << lines[4];
  EXPECT_TRUE(lines[4].ends_with("layout(std140) uniform FrameBlock {")) << lines[4];
  EXPECT_NE(lines[4].find("precision highp usampler2D;"), std::string::npos);
  EXPECT_EQ(lines[7], "uniform highp usampler2D u_lists;");
  EXPECT_EQ(lines[8], "uniform sampler2D u_textures[5];");
  EXPECT_EQ(lines[9], "layout(r32ui, binding = 0) uniform coherent uimage2D u_counts;") << "images stay as written";
  EXPECT_EQ(lines[10], "layout(location = 0) in vec3 a_position;") << "vertex inputs keep their locations";
  EXPECT_EQ(lines[11], "flat out uint v_id;") << "ES 3.00 matches stage outputs by name";
  EXPECT_EQ(lines[12], "");
  const std::vector<GlslBinding> expected{{"FrameBlock", 0, 1, true}, {"u_lists", 3, 1, false}, {"u_textures", 4, 5, false}};
  EXPECT_EQ(out.bindings, expected);
}

TEST(GlslDialect, Gl41KeepsStageLocationsAndNeedsNoPrecision) {
  const DialectText out = to_dialect(kShader, GL_VERTEX_SHADER, gl41());
  const std::vector<std::string> lines = lines_of(out.text);
  EXPECT_EQ(lines[0], "#version 410 core");
  EXPECT_EQ(lines[4], "layout(std140) uniform FrameBlock {");
  EXPECT_EQ(lines[11], "layout(location = 1) flat out uint v_id;");
  EXPECT_EQ(out.bindings.size(), 3u);
}

TEST(GlslDialect, FragmentInputsLoseTheirLocationsOutputsKeepThem) {
  const DialectText out = to_dialect(
      "#version 450 core\nlayout(location = 2) smooth in vec2 v_uv;\nlayout(location = 1) out vec4 o_color;\nvoid main() {}\n",
      GL_FRAGMENT_SHADER, es30());
  const std::vector<std::string> lines = lines_of(out.text);
  EXPECT_TRUE(lines[1].ends_with("smooth in vec2 v_uv;")) << lines[1];
  EXPECT_EQ(lines[1].find("location"), std::string::npos);
  EXPECT_EQ(lines[2], "layout(location = 1) out vec4 o_color;");
}

TEST(GlslDialect, ValuesPassedThroughAMacroLoseTheirLocationsInBothStages) {
  // common/mesh_interface.glsl declares both stages' side in one file: `out` or `in` through MESH_VARYING.
  const std::string text = "#version 450 core\nlayout(location = 0) in vec3 a_position;\n"
                           "layout(location = 10) flat MESH_VARYING uint v_material;\nlayout(location=4) MESH_VARYING vec2 v_uv[5];\n"
                           "layout(location = 0) out uint out_id;\n";
  const std::vector<std::string> vertex = lines_of(to_dialect(text, GL_VERTEX_SHADER, es30()).text);
  EXPECT_TRUE(vertex[1].ends_with("layout(location = 0) in vec3 a_position;")) << vertex[1];
  EXPECT_EQ(vertex[2], "flat MESH_VARYING uint v_material;");
  EXPECT_EQ(vertex[3], "MESH_VARYING vec2 v_uv[5];");
  const std::vector<std::string> fragment = lines_of(to_dialect(text, GL_FRAGMENT_SHADER, es30()).text);
  EXPECT_EQ(fragment[2], "flat MESH_VARYING uint v_material;");
  EXPECT_EQ(fragment[4], "layout(location = 0) out uint out_id;");
  EXPECT_EQ(lines_of(to_dialect(text, GL_VERTEX_SHADER, gl41()).text)[2], "layout(location = 10) flat MESH_VARYING uint v_material;");
}

TEST(GlslDialect, OneNameWithTwoBindingsIsRefusedNamingIt) {
  try {
    (void)to_dialect("#version 450 core\n#ifdef A\nlayout(binding = 0) uniform sampler2D u_x;\n#else\n"
                     "layout(binding = 1) uniform sampler2D u_x;\n#endif\n",
                     GL_FRAGMENT_SHADER, es30());
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("u_x has binding 0 in one place and 1 in another"), std::string::npos) << e.what();
  }
}

// Every stage the tier can compile, with every branch in its text: one
// binding per name, so the rewrite is right whatever the defines choose.
TEST(GlslDialect, EveryShaderInTheRepositoryKeepsOneBindingPerName) {
  std::size_t stages = 0;
  for (const fs::path& folder : default_shader_path()) {
    for (const auto& entry : fs::recursive_directory_iterator(folder)) {
      const std::string ext = entry.path().extension().string();
      if (ext != ".vert" && ext != ".frag") continue;
      const std::string file = fs::relative(entry.path(), folder).generic_string();
      const PreprocessedShader source = preprocess_shader({folder}, file, {});
      EXPECT_NO_THROW((void)to_dialect(source.text, ext == ".vert" ? GL_VERTEX_SHADER : GL_FRAGMENT_SHADER, es30())) << file;
      ++stages;
    }
  }
  EXPECT_GT(stages, 20u);
}

}  // namespace
}  // namespace atrium::gfx
