// The visibility buffer's two ways to its materials' textures
// (--material-binding): bindless, one dispatch over every tile sampling by
// handle, draws forward's picture on the built-in scene, on Sponza (alpha-
// tested foliage, normal maps, blended surfaces) and with MSAA, without the
// classification pass; where the context lacks ARB_bindless_texture, auto
// takes the bound path and bindless is refused in one line; the bound path's
// tile lists grow with the samples, not the materials, and it draws forward's
// picture where bindless is the default too. This program runs twice under
// ctest: on the system's llvmpipe, which lacks the extension, and on Mesa's
// zink over lavapipe (scripts/install-zink.sh), which has it; each run skips
// the tests that need what its driver lacks or that others already run there.
#include <algorithm>
#include <filesystem>
#include <string>

#include "app/world.hpp"
#include "assets/image.hpp"
#include "gfx/gl_features.hpp"
#include "gfx/limits.hpp"
#include "support/forward_comparison.hpp"
#include "support/gl_test.hpp"

namespace atrium {
namespace {

namespace fs = std::filesystem;
using testing::kSize;

const fs::path kSponza = fs::path(ATRIUM_TESTDATA_DIR) / "scenes/sponza-crytek/Sponza.gltf";

TechniqueOptions binding(MaterialBinding binding, int msaa = 1) {
  TechniqueOptions options;
  options.material_binding = binding;
  options.msaa = msaa;
  return options;
}

bool ran_pass(World& world, const std::string& name) {
  const auto& passes = world.renderer().timer().latest();
  return std::any_of(passes.begin(), passes.end(), [&](const gfx::PassTime& pass) { return pass.name == name; });
}

class BindlessMaterials : public testing::GlTest {
 protected:
  void SetUp() override {
    testing::GlTest::SetUp();
    if (!gfx::gl_features().bindless_textures) {
      GTEST_SKIP() << "this context lacks GL_ARB_bindless_texture; ctest runs these on zink (scripts/install-zink.sh)";
    }
  }
};

TEST_F(BindlessMaterials, AutoTakesBindlessAndDrawsForwardsPictureFromEveryView) {
  World world({.scene = "atrium", .mode = "forward", .size = kSize});
  // On zink one glint of view 2 is 12 levels off: its specular, from the same
  // material inputs (the debug views agree to the level), evaluates through
  // SPIR-V and lavapipe in another order than forward's fragment shader.
  testing::expect_forward_picture_from_every_view(world, "visibility-buffer", "bindless_atrium", 0.0005);
  EXPECT_EQ(world.renderer().stats().technique_variant, "material binding bindless");
  // One dispatch over every tile gives the background too: no classification pass.
  EXPECT_TRUE(ran_pass(world, "resolve"));
  EXPECT_FALSE(ran_pass(world, "material classification"));
}

TEST_F(BindlessMaterials, SponzaMatchesForward) {
  if (!fs::exists(kSponza)) GTEST_SKIP() << kSponza << " is not here";
  World world({.scene = kSponza.string(), .lights = 64, .mode = "forward", .size = kSize,
               .technique_options = binding(MaterialBinding::Bindless)});
  testing::expect_forward_picture_from_every_view(world, "visibility-buffer", "bindless_sponza", 0.002);
}

// Views 1 and 2 only: each MSAA view costs zink seconds of shader compiling and drawing.
TEST_F(BindlessMaterials, MsaaShadesEachSurfaceAsForwardDoes) {
  World world({.scene = "atrium", .mode = "forward", .size = kSize, .technique_options = binding(MaterialBinding::Bindless, 4)});
  for (const int view : {1, 2}) {
    world.set_view(view);
    world.set_mode("forward");
    world.frame(0.0);
    const assets::Image reference = world.renderer().read_output();
    world.set_mode("visibility-buffer");
    world.frame(0.0);
    const assets::Image image = world.renderer().read_output();
    assets::write_png("compare_bindless_msaa_view" + std::to_string(view) + ".png", image);
    EXPECT_GE(assets::psnr(reference, image), kMinimumPsnr) << "view " << view;
    EXPECT_LE(testing::share_differing(reference, image, 8), 0.002) << "view " << view;
  }
}

using MaterialBindingWithoutBindless = testing::GlTest;

TEST_F(MaterialBindingWithoutBindless, AutoBindsPerMaterialAndBindlessIsRefusedInOneLine) {
  if (gfx::gl_features().bindless_textures) GTEST_SKIP() << "this context has GL_ARB_bindless_texture";
  World world({.scene = "atrium", .mode = "visibility-buffer", .size = kSize});
  world.frame(0.0);
  EXPECT_EQ(world.renderer().stats().technique_variant, "material binding bound");
  EXPECT_TRUE(ran_pass(world, "material classification"));
  try {
    World bindless({.scene = "atrium", .mode = "visibility-buffer", .size = kSize, .technique_options = binding(MaterialBinding::Bindless)});
    bindless.frame(0.0);
    FAIL() << "bindless ran without GL_ARB_bindless_texture";
  } catch (const gfx::ResourceLimitError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("GL_ARB_bindless_texture"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

// The bound path runs on every context; these run on both of ctest's.
using BoundMaterials = testing::GlTest;

// Where auto takes bindless (zink), the bound path asked for by name draws
// forward's picture too: the built-in scene and Sponza from every view. On
// zink its binary search over the units once took the block's length(),
// which zink gave as the whole buffer's: one material of many was shaded.
// Where auto binds per material (llvmpipe), Modes/TechniqueMatchesForward and
// SponzaScene draw the same.
TEST_F(BoundMaterials, DrawForwardsPictureWhereBindlessIsTheDefault) {
  if (!gfx::gl_features().bindless_textures) GTEST_SKIP() << "auto binds per material here: the technique comparisons draw it";
  World world({.scene = "atrium", .lights = 64, .mode = "forward", .size = kSize, .technique_options = binding(MaterialBinding::Bound)});
  testing::expect_forward_picture_from_every_view(world, "visibility-buffer", "bound_atrium", 0.0005);
  EXPECT_EQ(world.renderer().stats().technique_variant, "material binding bound");
  if (!fs::exists(kSponza)) GTEST_SKIP() << kSponza << " is not here";
  World sponza_world({.scene = kSponza.string(), .lights = 64, .mode = "forward", .size = kSize,
                      .technique_options = binding(MaterialBinding::Bound)});
  testing::expect_forward_picture_from_every_view(sponza_world, "visibility-buffer", "bound_sponza", 0.002);
}

// Bytes of the frame's resource `name` (0: the frame has none).
std::size_t resource_bytes(World& world, const std::string& name) {
  for (const render::ResourceUse& use : world.renderer().graph().used_resources()) {
    if (use.name == name) return use.bytes;
  }
  return 0;
}

// Blender's sheet of 384 faces, each its own material: more than a tile can
// show even with 4x MSAA (64 pixels x 4 samples). The bound path draws
// forward's picture, and its tile lists hold what a tile can show, 4 bytes a
// tile for each of the fewer of 64 x samples and the materials, where a list
// of every tile per material took 384 (and grew to 650 MB for 1,100 materials
// at 4096x2304).
TEST_F(BoundMaterials, TileListsGrowWithSamplesNotMaterials) {
  const std::string sheet = std::string(ATRIUM_SOURCE_DIR) + "/tests/data/gltf-tools/blender-materials.glb";
  constexpr std::size_t kTiles = 20 * 12;  // 8x8 tiles of 160x90
  for (const int samples : {1, 4}) {
    World world({.scene = sheet, .lights = 32, .mode = "forward", .size = kSize, .technique_options = binding(MaterialBinding::Bound, samples)});
    testing::expect_forward_picture_from_every_view(world, "visibility-buffer", "materials_384_x" + std::to_string(samples), 0.0);
    // From the front the whole sheet is in view: every material is in the draw list.
    world.set_view(1);
    world.frame(0.0);
    const std::size_t slots = 64 * static_cast<std::size_t>(samples);
    EXPECT_EQ(resource_bytes(world, "material-tiles"), kTiles * slots * 4) << samples << " samples";
    EXPECT_EQ(resource_bytes(world, "tile-materials"), kTiles * (slots + 1) * 4) << samples << " samples";
    EXPECT_GE(resource_bytes(world, "material-dispatch"), 384u * 24) << samples << " samples";
  }
}

// A material over more tiles than GL promises work groups along a dispatch's
// x (65,535): tinygltf's cube filling a 2304x2048 image, 73,728 tiles of one
// material, which its resolve dispatch folds into two rows.
TEST_F(BoundMaterials, AMaterialOverMoreTilesThanADispatchRowIsShadedEverywhere) {
  const fs::path cube = fs::path(ATRIUM_TESTDATA_DIR) / "gltf/tinygltf/Cube/Cube.gltf";
  if (!fs::exists(cube)) GTEST_SKIP() << cube << " is not here";
  // The visibility buffer first: a tile it leaves unshaded keeps no earlier mode's picture.
  World world({.scene = cube.string(), .lights = 16, .mode = "visibility-buffer", .size = {2304, 2048},
               .technique_options = binding(MaterialBinding::Bound),
               .camera = assets::NamedView{"face", glm::vec3(0.0f, 0.0f, 1.5f), 0.0f, 0.0f}});
  world.frame(0.0);
  const assets::Image image = world.renderer().read_output();
  world.set_mode("forward");
  world.frame(0.0);
  const assets::Image reference = world.renderer().read_output();
  EXPECT_GE(assets::psnr(reference, image), kMinimumPsnr);
  EXPECT_LE(testing::share_differing(reference, image, 8), 0.0001);
}

}  // namespace
}  // namespace atrium
