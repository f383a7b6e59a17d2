// The compact G-buffer's packing: octahedral normals survive their 2x16-bit
// encoding everywhere on the sphere (poles, the folded lower half, the seams),
// the two layouts cost the bytes per pixel the docs state, and each deferred
// mode draws nearly the same picture with either (docs/techniques.md quotes it).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <optional>

#include <glm/glm.hpp>

#include "app/cli.hpp"
#include "app/world.hpp"
#include "gfx/depth.hpp"
#include "render/frame_graph.hpp"
#include "assets/image.hpp"
#include "support/compute_probe.hpp"
#include "support/gl_test.hpp"
#include "support/modes.hpp"
#include "render/lighting/gbuffer.hpp"

namespace atrium {
namespace {

namespace fs = std::filesystem;
using CompactGBuffer = testing::GlTest;
using GBufferBytes = testing::GlTest;

std::vector<glm::vec4> sphere_directions() {
  std::vector<glm::vec4> directions;
  // A Fibonacci sphere covers every region evenly...
  constexpr int kCount = 20000;
  const float golden = std::numbers::pi_v<float> * (3.0f - std::sqrt(5.0f));
  for (int i = 0; i < kCount; ++i) {
    const float y = 1.0f - 2.0f * (static_cast<float>(i) + 0.5f) / kCount;
    const float r = std::sqrt(1.0f - y * y);
    directions.emplace_back(r * std::cos(golden * static_cast<float>(i)), y, r * std::sin(golden * static_cast<float>(i)), 0.0f);
  }
  // ...and the axes and the octahedron's edges are where encodings break.
  for (const glm::vec3 d : {glm::vec3(1, 0, 0), glm::vec3(-1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, -1, 0), glm::vec3(0, 0, 1),
                            glm::vec3(0, 0, -1), glm::vec3(1, 1, 0), glm::vec3(-1, 0, -1), glm::vec3(0, -1, -1e-7f),
                            glm::vec3(1, -1, -1), glm::vec3(-1e-7f, 1e-7f, -1)}) {
    directions.emplace_back(glm::normalize(d), 0.0f);
  }
  return directions;
}

TEST_F(CompactGBuffer, OctahedralNormalsRoundTripWithinATenThousandthOfARadian) {
  const std::vector<glm::vec4> directions = sphere_directions();
  const auto decoded = testing::evaluate_glsl<glm::vec4>(
      "#define COMPACT_GBUFFER\n#include \"common/frame.glsl\"\n#include \"common/surface.glsl\"\n#include \"common/gbuffer.glsl\"\n",
      "vec4", "vec4",
      "vec4(octahedral_decode(unpackUnorm2x16(packUnorm2x16(octahedral_encode(value.xyz) * 0.5 + 0.5)) * 2.0 - 1.0), 0.0)",
      directions);
  double worst = 0.0;
  for (std::size_t i = 0; i < directions.size(); ++i) {
    const glm::dvec3 in(directions[i]), out(decoded[i]);
    ASSERT_NEAR(glm::length(out), 1.0, 1e-5) << i;
    // atan2 of sine and cosine: acos loses small angles to rounding.
    const double angle = std::atan2(glm::length(glm::cross(in, out)), glm::dot(in, out));
    worst = std::max(worst, angle);
    EXPECT_LT(angle, 1e-4) << "normal (" << in.x << ", " << in.y << ", " << in.z << ")";
  }
  RecordProperty("worst_angle_radians", std::to_string(worst));
}

// The bytes each layout costs come from its targets' GL formats (and the
// renderer's depth-stencil), as the driver sizes them; README and --help state
// them from the same function.
TEST_F(GBufferBytes, AreWhatTheirGlFormatsHoldAndWhatTheDocsSay) {
  auto gl_bits = [](GLenum format) {
    GLint total = 0;
    for (const GLenum size : {GL_INTERNALFORMAT_RED_SIZE, GL_INTERNALFORMAT_GREEN_SIZE, GL_INTERNALFORMAT_BLUE_SIZE,
                              GL_INTERNALFORMAT_ALPHA_SIZE, GL_INTERNALFORMAT_DEPTH_SIZE, GL_INTERNALFORMAT_STENCIL_SIZE}) {
      GLint bits = 0;
      glGetInternalformativ(GL_TEXTURE_2D, format, size, 1, &bits);
      total += bits;
    }
    return total;
  };
  for (const auto layout : {GBufferLayout::Full, GBufferLayout::Compact, GBufferLayout::Thin}) {
    std::size_t bytes = 0;
    for (const lighting::GBuffer::Target& target : lighting::GBuffer::targets(layout)) {
      const std::size_t texel = render::texture_bytes({target.format, {1, 1}, 1});
      EXPECT_EQ(static_cast<GLint>(texel * 8), gl_bits(target.format)) << target.name;
      bytes += texel;
    }
    // DEPTH32F_STENCIL8: 40 bits of data, stored as 64 (GL_FLOAT_32_UNSIGNED_INT_24_8_REV).
    EXPECT_EQ(gl_bits(gfx::kDepthStencilFormat), 40);
    EXPECT_EQ(lighting::GBuffer::bytes_per_pixel(layout), bytes + 8);
  }
  EXPECT_EQ(lighting::GBuffer::bytes_per_pixel(GBufferLayout::Full), 48u);
  EXPECT_EQ(lighting::GBuffer::bytes_per_pixel(GBufferLayout::Compact), 28u);
  std::ifstream readme(fs::path(ATRIUM_SOURCE_DIR) / "README.md");
  const std::string text((std::istreambuf_iterator<char>(readme)), std::istreambuf_iterator<char>());
  for (const auto& [name, layout] : {std::pair{"full", GBufferLayout::Full}, std::pair{"compact", GBufferLayout::Compact}}) {
    const std::string stated = std::to_string(lighting::GBuffer::bytes_per_pixel(layout)) + " B/px";
    std::string row = "`";
    row.append(name).append("` (").append(std::to_string(lighting::GBuffer::targets(layout).size())).append(" targets, ").append(stated);
    EXPECT_NE(text.find(row), std::string::npos)
        << name << ": README states another size than " << stated;
    EXPECT_NE(help_text(Command::Render).find(std::string(name) + " (" + std::to_string(lighting::GBuffer::targets(layout).size()) +
                                              " targets, " + stated),
              std::string::npos)
        << name;
  }
}

// The technique table's GBufferUse column is what each technique does: no
// G-buffer, the layout --gbuffer chose, or a layout of its own.
TEST_F(CompactGBuffer, EachTechniqueKeepsTheGBufferItsTableRowSays) {
  for (const techniques::TechniqueInfo& info : techniques::technique_table()) {
    World world({.scene = "atrium", .lights = 4u, .mode = std::string(info.name), .size = {32, 18},
                 .technique_options = testing::with_layout(GBufferLayout::Compact)});
    world.frame(0.0);
    const std::optional<lighting::GBuffer::Found> gbuffer = lighting::GBuffer::find(world.renderer().graph());
    switch (info.gbuffer) {
      case techniques::GBufferUse::None: EXPECT_FALSE(gbuffer.has_value()) << info.name; break;
      case techniques::GBufferUse::Chosen:
        ASSERT_TRUE(gbuffer.has_value()) << info.name;
        EXPECT_EQ(gbuffer->layout, GBufferLayout::Compact) << info.name;
        break;
      case techniques::GBufferUse::Own:
        ASSERT_TRUE(gbuffer.has_value()) << info.name;
        EXPECT_NE(gbuffer->layout, GBufferLayout::Compact) << info.name;
        break;
    }
  }
}

TEST_F(CompactGBuffer, DrawsWhatTheFullLayoutDrawsInEveryDeferredMode) {
  World full({.scene = "atrium", .mode = "deferred", .size = {160, 90}, .technique_options = testing::with_layout(GBufferLayout::Full)});
  World compact({.scene = "atrium", .mode = "deferred", .size = {160, 90}, .technique_options = testing::with_layout(GBufferLayout::Compact)});
  for (const techniques::TechniqueInfo& info : techniques::technique_table()) {
    if (info.gbuffer != techniques::GBufferUse::Chosen) continue;  // the layout changes nothing there
    const std::string mode(info.name);
    double worst = 1e9;
    for (int view = 1; view <= 5; ++view) {
      for (World* world : {&full, &compact}) {
        world->set_mode(mode);
        world->set_view(view);
        world->frame(0.0);
      }
      const double psnr = assets::psnr(full.renderer().read_output(), compact.renderer().read_output());
      worst = std::min(worst, psnr);
      EXPECT_GE(psnr, 50.0) << mode << " view " << view;
    }
    RecordProperty(mode + "_worst_psnr_db", std::to_string(worst));
  }
}

}  // namespace
}  // namespace atrium
