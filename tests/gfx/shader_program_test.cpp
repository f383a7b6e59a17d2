#include <filesystem>
#include <fstream>

#include "gfx/shader_library.hpp"
#include "gfx/shader_program.hpp"
#include "support/gl_test.hpp"

namespace atrium::gfx {
namespace {
namespace fs = std::filesystem;

class ShaderFiles : public testing::GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    root_ = fs::temp_directory_path() / ("atrium_shader_test_" + std::to_string(::getpid()));
    fs::create_directories(root_ / "lib");
  }
  void TearDown() override {
    fs::remove_all(root_);
    GlTest::TearDown();
  }
  void write(const std::string& name, const std::string& text) {
    fs::create_directories((root_ / name).parent_path());
    std::ofstream(root_ / name) << text;
  }
  std::string load_error(const std::vector<std::string>& files, const std::vector<ShaderDefine>& defines = {}) {
    try {
      (void)ShaderProgram::load(files, defines, {root_});
    } catch (const ShaderError& e) {
      return e.what();
    }
    return "(no error)";
  }
  static constexpr const char* kVertex = "#version 450 core\nvoid main() { gl_Position = vec4(0.0); }\n";
  fs::path root_;
};

TEST_F(ShaderFiles, IncludesAreResolvedOnceAndDefinesFollowTheVersionLine) {
  write("lib/b.glsl", "float b_value() { return 0.25; }\n");
  write("lib/a.glsl", "#include \"b.glsl\"\nfloat a_value() { return b_value() * 2.0; }\n");
  write("main.frag",
        "#version 450 core\n#include \"lib/a.glsl\"\n#include \"lib/a.glsl\"\nout vec4 color;\n"
        "void main() {\n#if VARIANT == 3\n  color = vec4(a_value());\n#else\n  undefined_symbol;\n#endif\n}\n");
  write("main.vert", kVertex);
  const PreprocessedShader pre = preprocess_shader({root_}, "main.frag", {{"VARIANT", "3"}});
  EXPECT_EQ(pre.text.rfind("#version 450 core\n#define VARIANT 3\n", 0), 0u);
  EXPECT_EQ(pre.files, (std::vector<std::string>{"main.frag", "lib/a.glsl", "lib/b.glsl"}));
  const ShaderProgram program = ShaderProgram::load({"main.vert", "main.frag"}, {{"VARIANT", "3"}}, {root_});
  EXPECT_NE(program.id(), 0u);
  // Without the define the #else branch compiles, and fails.
  EXPECT_NE(load_error({"main.vert", "main.frag"}).find("main.frag:9:"), std::string::npos);
}

// A file is pasted in once, where it is first included: first included inside
// a conditional block, it is missing wherever that block compiles out, and a
// later #include outside the block is refused naming both lines. Inside the
// same block (or a block within it) a second #include is fine.
TEST_F(ShaderFiles, AFileFirstIncludedInsideAConditionalIsNotIncludedOutsideIt) {
  write("lib/helper.glsl", "float helper() { return 0.5; }\n");
  write("lib/user.glsl", "#include \"helper.glsl\"\nfloat user() { return helper(); }\n");
  write("main.vert", kVertex);
  write("trap.frag",
        "#version 450 core\n#ifdef FANCY\n#include \"lib/helper.glsl\"\n#endif\n#include \"lib/user.glsl\"\nout vec4 c;\n"
        "void main() { c = vec4(user()); }\n");
  EXPECT_EQ(load_error({"main.vert", "trap.frag"}),
            "lib/user.glsl:1: error: \"lib/helper.glsl\" is first included inside a conditional block (trap.frag:3), and a file is "
            "included once: where that block compiles out it is missing here too; include it before the block");
  // An #else is a block of its own.
  write("branches.frag",
        "#version 450 core\n#ifdef FANCY\n#include \"lib/helper.glsl\"\n#else\n#include \"lib/user.glsl\"\n#endif\n"
        "out vec4 c;\nvoid main() { c = vec4(0.0); }\n");
  EXPECT_NE(load_error({"main.vert", "branches.frag"}).find("lib/user.glsl:1: error:"), std::string::npos);
  // Included again inside the block it was first included in, or first included outside any: loads.
  write("inside.frag",
        "#version 450 core\n#include \"lib/helper.glsl\"\n#if 1\n#include \"lib/user.glsl\"\n#endif\nout vec4 c;\n"
        "void main() { c = vec4(user()); }\n");
  EXPECT_EQ(load_error({"main.vert", "inside.frag"}), "(no error)");
  write("nested.frag",
        "#version 450 core\n#ifndef PLAIN\n#include \"lib/helper.glsl\"\n  #  if 1\n#include \"lib/user.glsl\"\n#endif\n"
        "out vec4 c;\nvoid main() { c = vec4(user()); }\n#else\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n#endif\n");
  EXPECT_EQ(load_error({"main.vert", "nested.frag"}), "(no error)");
}

TEST_F(ShaderFiles, CompileErrorsNameTheIncludedFileAndLine) {
  write("lib/bad.glsl", "// a helper\nfloat ok() { return 1.0; }\n\nfloat broken() { return nope; }\n");
  write("main.frag", "#version 450 core\n#include \"lib/bad.glsl\"\nout vec4 c;\nvoid main() { c = vec4(ok()); }\n");
  write("main.vert", kVertex);
  const std::string error = load_error({"main.vert", "main.frag"});
  EXPECT_NE(error.find("lib/bad.glsl:4:"), std::string::npos) << error;
  EXPECT_NE(error.find("nope"), std::string::npos) << error;
}

TEST_F(ShaderFiles, CompileErrorLinesInTheMainFileCountItsOwnLinesWithDefines) {
  write("main.frag", "#version 450 core\n#include \"lib/x.glsl\"\nout vec4 c;\nvoid main() {\n  c = vec4(missing);\n}\n");
  write("lib/x.glsl", "float x() { return 1.0; }\n");
  write("main.vert", kVertex);
  const std::string error = load_error({"main.vert", "main.frag"}, {{"A", "1"}, {"B", "2"}});
  EXPECT_NE(error.find("main.frag:5:"), std::string::npos) << error;
}

TEST_F(ShaderFiles, MissingIncludeAndMissingFileAreNamed) {
  write("main.frag", "#version 450 core\n#include \"nope.glsl\"\nvoid main() {}\n");
  write("main.vert", kVertex);
  EXPECT_EQ(load_error({"main.vert", "main.frag"}), "main.frag:2: error: cannot find included file \"nope.glsl\"");
  EXPECT_NE(load_error({"main.vert", "absent.frag"}).find("absent.frag: cannot open shader file"), std::string::npos);
  EXPECT_NE(load_error({"main.vert", "main.txt"}).find("unknown shader stage"), std::string::npos);
}

TEST_F(ShaderFiles, LinkErrorsNameTheProgramsFiles) {
  write("main.frag", "#version 450 core\nout vec4 c;\nvec4 declared_only();\nvoid main() { c = declared_only(); }\n");
  write("main.vert", kVertex);
  const std::string error = load_error({"main.vert", "main.frag"});
  EXPECT_NE(error.find("main.vert + main.frag: link failed"), std::string::npos) << error;
}

TEST(ShaderLog, NvidiaAndMesaFormatsAreMappedToFiles) {
  const std::vector<std::string> files{"forward/shade.frag", "common/brdf.glsl"};
  EXPECT_EQ(map_shader_log("0:12(5): error: `x' undeclared\n", files), "forward/shade.frag:12: error: `x' undeclared\n");
  EXPECT_EQ(map_shader_log("1(7) : error C1008: undefined variable \"y\"\n", files),
            "common/brdf.glsl:7: error C1008: undefined variable \"y\"\n");
}

TEST_F(ShaderFiles, TheEnginesShadersCompile) {
  EXPECT_NO_THROW((void)ShaderProgram::load({"common/mesh.vert", "forward/shade.frag"}));
  EXPECT_NO_THROW((void)ShaderProgram::load({"post/fullscreen.vert", "post/tonemap.frag"}));
}

TEST_F(ShaderFiles, TheLibraryCompilesEachProgramOnce) {
  ShaderLibrary library;
  const std::int64_t before = live_gl_objects(GlKind::Program);
  ShaderProgram& a = library.get({"common/mesh.vert", "forward/shade.frag"});
  ShaderProgram& b = library.get({"common/mesh.vert", "forward/shade.frag"});
  ShaderProgram& c = library.get({"common/mesh.vert", "forward/shade.frag"}, {{"VARIANT", "2"}});
  EXPECT_EQ(&a, &b);
  EXPECT_NE(&a, &c);
  EXPECT_EQ(library.size(), 2u);
  EXPECT_EQ(live_gl_objects(GlKind::Program), before + 2);
}

using DebugOutput = testing::GlTest;

TEST_F(DebugOutput, AGlErrorIsReportedInTheCallThatCausedIt) {
  EXPECT_EQ(gl_error_count(), 0u);
  glBindBuffer(GL_ARRAY_BUFFER, 987654);  // never generated: GL_INVALID_OPERATION in core profile
  EXPECT_EQ(gl_error_count(), 1u);
  EXPECT_FALSE(last_gl_error().empty());
  reset_gl_error_count();  // the error was expected
  glGetError();
}

}  // namespace
}  // namespace atrium::gfx
