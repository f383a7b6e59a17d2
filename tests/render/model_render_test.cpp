// OBJ, FBX and DDS files written by other tools (tests/data/model-tools) drawn
// beside what they were made from: each model covers the pixels its glTF source
// covers at the same depths, from the same cameras, in every mode; DDS textures
// (BC1 and BC3 blocks, sampled compressed, or decoded where the driver cannot)
// draw their PNG twins' picture, also over the texture cap; and a
// normal map tilts a surface alike whether it is RGBA or two-channel BC5, in
// OpenGL's convention or (flagged, as Bistro's) DirectX's.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include <assimp/Exporter.hpp>
#include <assimp/Importer.hpp>
#include <assimp/scene.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "app/cli.hpp"
#include "app/world.hpp"
#include "render/gpu_assets.hpp"
#include "assets/image.hpp"
#include "assets/mesh_builder.hpp"
#include "assets/scene_file.hpp"
#include "support/adopt_views.hpp"
#include "support/gl_test.hpp"
#include "support/uploaded_texture.hpp"
#include "render/techniques/technique.hpp"

namespace atrium {
namespace {
namespace fs = std::filesystem;

using testing::kSize;
const fs::path kFixtures = fs::path(ATRIUM_SOURCE_DIR) / "tests/data/model-tools";
const fs::path kTestdata = fs::path(ATRIUM_TESTDATA_DIR);

using ModelRender = testing::GlTest;

struct Frame {
  assets::Image image;
  std::vector<float> depth;
};

// The model's frames from the views (and under the lights) of `like`, or its
// own auto-framed ones.
std::vector<Frame> render(const fs::path& model, const std::string& mode, const assets::SceneDescription* like,
                          assets::SceneDescription* own = nullptr, std::size_t* texture_bytes = nullptr) {
  assets::AssetManager assets;
  assets::LoadReport report;
  assets::SceneDescription scene = assets::load_model_scene(model, assets, 24, report);
  if (own) *own = scene;
  if (like) testing::adopt_views_and_lights(scene, *like);
  WorldOptions options;
  options.mode = mode;
  options.size = kSize;
  World world(std::move(assets), std::move(scene), options);
  if (texture_bytes) *texture_bytes = world.registry().resource<render::GpuAssets>().texture_bytes();
  std::vector<Frame> frames;
  for (int view = 1; view <= 4; ++view) {
    world.set_view(view);
    world.frame(0.0);
    frames.push_back({world.renderer().read_output(), world.renderer().read_view_depth()});
  }
  return frames;
}

// Of the pixels either frame covers, the share both cover within 1% of depth.
double same_surface_share(const Frame& a, const Frame& b) {
  std::size_t either = 0, same = 0;
  for (std::size_t i = 0; i < a.depth.size(); ++i) {
    const bool in_a = std::isfinite(a.depth[i]), in_b = std::isfinite(b.depth[i]);
    if (!in_a && !in_b) continue;
    ++either;
    same += in_a && in_b && std::abs(a.depth[i] - b.depth[i]) <= 0.01f * a.depth[i];
  }
  return either == 0 ? 1.0 : static_cast<double>(same) / static_cast<double>(either);
}

TEST_F(ModelRender, ObjAndFbxCoverTheirGltfSourcesPixelsAtTheirDepthsInEveryMode) {
  const std::pair<std::string, std::string> pairs[] = {
      {"torusknot.assimp.obj", "torusknot"},
      {"torusknot.blender-yup.fbx", "torusknot"},
      {"subpass_scene_opaque.blender-zup.fbx", "subpass_scene_opaque"},
  };
  for (const auto& [file, source_name] : pairs) {
    assets::SceneDescription source;
    const std::vector<Frame> expected = render(kTestdata / "gltf/blender-exports" / (source_name + ".gltf"), "forward", nullptr, &source);
    for (const std::string& mode : techniques::mode_names()) {
      const std::vector<Frame> actual = render(kFixtures / file, mode, &source);
      for (std::size_t v = 0; v < actual.size(); ++v) {
        if (mode == "forward") assets::write_png("model_" + file + "_view" + std::to_string(v + 1) + ".png", actual[v].image);
        // Edges may round to the other side at a pixel's centre.
        EXPECT_GE(same_surface_share(expected[v], actual[v]), 0.99) << file << " " << mode << " view " << v + 1;
      }
    }
  }
}

// The assimp cube with its MTL naming `texture`, in a folder of its own.
fs::path textured_cube(const std::string& texture, const std::string& folder_name) {
  const fs::path folder = fs::temp_directory_path() / ("atrium_dds_" + std::to_string(::getpid()) + "_" + folder_name);
  fs::create_directories(folder);
  fs::copy_file(kFixtures / "cube.assimp.obj", folder / "cube.assimp.obj", fs::copy_options::overwrite_existing);
  fs::copy_file(kFixtures / texture, folder / texture, fs::copy_options::overwrite_existing);
  std::ofstream(folder / "cube.assimp.mtl") << "newmtl Cube\nKd 1 1 1\nmap_Kd " << texture << "\nnewmtl $Material_1\nKd 1 1 1\n";
  return folder / "cube.assimp.obj";
}

TEST_F(ModelRender, DdsTexturesDrawTheirPngTwinsPicture) {
  const bool samples_blocks = epoxy_has_gl_extension("GL_EXT_texture_compression_s3tc");
  for (const std::string name : {"bricks", "leaves"}) {
    const fs::path png = textured_cube(name + ".png", name + "_png");
    assets::SceneDescription scene;
    std::size_t png_bytes = 0;
    const std::vector<Frame> expected = render(png, "forward", nullptr, &scene, &png_bytes);
    for (const std::string& format : {name == "bricks" ? std::string("bc1") : std::string("bc3"), std::string("rgba")}) {
      const fs::path dds = textured_cube(name + "." + format + ".dds", name + "_" + format);
      std::size_t dds_bytes = 0;
      (void)render(dds, "forward", &scene, nullptr, &dds_bytes);
      // The memory estimate counts blocks as uploaded: BC1 is 8x smaller than
      // RGBA8, BC3 4x (the 1x1 defaults and mip chains aside); decoded, as
      // many bytes as the PNG's.
      if (format != "rgba" && samples_blocks) EXPECT_LT(dds_bytes * (format == "bc1" ? 6 : 3), png_bytes) << name << " " << dds_bytes << " against " << png_bytes;
      if (format != "rgba" && !samples_blocks) EXPECT_EQ(dds_bytes, png_bytes) << name;
      for (const std::string& mode : {std::string("forward"), std::string("deferred")}) {
        const std::vector<Frame> actual = render(dds, mode, &scene);
        for (std::size_t v = 0; v < actual.size(); ++v) {
          assets::write_png("model_dds_" + name + "_" + format + "_" + mode + "_view" + std::to_string(v + 1) + ".png", actual[v].image);
          // Uncompressed DDS holds the PNG's texels; BC blocks lose some (a
          // BC1 texture alone measures about 35 dB against its source).
          EXPECT_GE(assets::psnr(expected[v].image, actual[v].image), format == "rgba" ? 45.0 : 30.0)
              << name << " " << format << " " << mode << " view " << v + 1;
        }
      }
      fs::remove_all(dds.parent_path());
    }
    fs::remove_all(png.parent_path());
  }
}

// Over --max-texture-size a DDS loads within the cap with one warning that
// says how: from its first mip level within it (uploaded as blocks, or decoded
// where the driver samples no S3TC), or, without a mip chain, decoded and
// downscaled; and it draws its PNG twin's picture at the cap. ctest
// render.decoded_blocks runs this where Mesa hides S3TC from the driver.
TEST_F(ModelRender, DdsOverTheTextureCapLoadsWithinItWithOneWarning) {
  const bool samples_bc1 = epoxy_has_gl_extension("GL_EXT_texture_compression_s3tc");
  std::cout << (samples_bc1 ? "S3TC blocks sampled by the driver\n" : "S3TC blocks decoded: the driver samples none\n");
  auto load = [](const fs::path& model) {
    return std::make_unique<World>(WorldOptions{.scene = model.string(), .lights = 24u, .size = kSize, .max_texture_size = 64});
  };
  const fs::path png = textured_cube("bricks.png", "capped_png");
  std::unique_ptr<World> twin = load(png);
  twin->frame(0.0);
  const assets::Image expected = twin->renderer().read_output();
  const std::pair<std::string, std::string> cases[] = {
      {"bricks.bc1.dds", samples_bc1 ? "uploaded from its mip level of 64x64" : "decoded from its mip level of 64x64"},
      {"bricks.bc1-nomips.dds", "decoded and downscaled to 64x64"}};
  for (const auto& [file, how] : cases) {
    const fs::path dds = textured_cube(file, "capped_" + file);
    std::unique_ptr<World> world = load(dds);
    const std::vector<std::string>& warnings = world->load_report().warnings;
    EXPECT_THAT(warnings, ::testing::Contains(::testing::HasSubstr("texture 0 '" + file + "' is 128x128, more than --max-texture-size allows (64); it is " + how)))
        << file;
    if (!samples_bc1) EXPECT_THAT(warnings, ::testing::Contains(::testing::HasSubstr("is BC1, which this driver cannot sample; it is decoded"))) << file;
    EXPECT_EQ(warnings.size(), samples_bc1 ? 1u : 2u) << file;
    EXPECT_EQ(testing::uploaded_size(*world), glm::ivec2(64, 64)) << file;
    world->frame(0.0);
    const assets::Image actual = world->renderer().read_output();
    assets::write_png("model_dds_capped_" + file + ".png", actual);
    EXPECT_GE(assets::psnr(expected, actual), 30.0) << file << ": BC1 blocks against the PNG, both at 64x64";
    fs::remove_all(dds.parent_path());
  }
  fs::remove_all(png.parent_path());
}

// The real Sponza as OBJ + MTL, written at test time by assimp's OBJ exporter
// from the glTF in ../shared (the route users of OBJ Sponza take): the same
// triangles at the same depths from every auto view, in every mode, with its
// textures found. Its picture differs where OBJ cannot say what glTF did (no
// metal-rough textures: the Phong convention's exponent sets roughness).
TEST_F(ModelRender, SponzaExportedAsObjDrawsTheGltfsSurfaces) {
  const fs::path sponza = kTestdata / "scenes/sponza-crytek/Sponza.gltf";
  if (!fs::exists(sponza)) GTEST_SKIP() << sponza << " is not here";
  const fs::path folder = fs::temp_directory_path() / ("atrium_sponza_obj_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  fs::create_directory_symlink(sponza.parent_path() / "textures", folder / "textures");
  {
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(sponza.string(), 0);
    ASSERT_TRUE(scene) << importer.GetErrorString();
    Assimp::Exporter exporter;
    ASSERT_EQ(exporter.Export(scene, "obj", (folder / "sponza.obj").string()), AI_SUCCESS) << exporter.GetErrorString();
  }
  assets::AssetManager gltf_assets, obj_assets;
  assets::LoadReport gltf_report, obj_report;
  const auto gltf_scene = assets::load_model_scene(sponza, gltf_assets, 0, gltf_report);
  const auto obj_scene = assets::load_model_scene(folder / "sponza.obj", obj_assets, 0, obj_report);
  auto triangles = [](const assets::AssetManager& assets, const assets::SceneDescription& scene) {
    std::size_t count = 0;
    for (const auto& instance : scene.instances) count += assets::triangle_count(assets.mesh_asset(instance.asset).meshes.at(instance.mesh));
    return count;
  };
  EXPECT_EQ(triangles(obj_assets, obj_scene), triangles(gltf_assets, gltf_scene));
  for (const std::string& warning : obj_report.warnings) EXPECT_EQ(warning.find("cannot be decoded"), std::string::npos) << warning;
  assets::SceneDescription lit;
  const std::vector<Frame> expected = render(sponza, "forward", nullptr, &lit);
  for (const std::string& mode : {std::string("forward"), std::string("deferred"), std::string("clustered-forward")}) {
    const std::vector<Frame> actual = render(folder / "sponza.obj", mode, &lit);
    for (std::size_t v = 0; v < actual.size(); ++v) {
      if (mode == "forward") assets::write_png("model_sponza_obj_view" + std::to_string(v + 1) + ".png", actual[v].image);
      EXPECT_GE(same_surface_share(expected[v], actual[v]), 0.99) << mode << " view " << v + 1;
    }
  }
  fs::remove_all(folder);
}

// A white quad facing the camera, lit from above and in front, its normal map
// `normal` (or none) read green-down when asked.
assets::Image normal_mapped_quad(std::optional<assets::TextureData> normal, bool green_down, const std::string& mode) {
  assets::AssetManager manager;
  assets::MeshAsset asset;
  assets::Material material;
  material.metallic_factor = 0.0f;
  material.roughness_factor = 1.0f;
  material.normal_green_down = green_down;
  if (normal) material.normal_texture.texture = manager.add_texture(std::move(*normal));
  asset.materials.push_back(material);
  asset.meshes.push_back({"quad", {assets::add_geometry(asset, assets::shapes::grid(glm::vec3(-2, -1.5f, 0), glm::vec3(4, 0, 0),
                                                                                     glm::vec3(0, 3, 0), 2, 2, 1.0f), 0)}});
  assets::SceneDescription scene;
  scene.instances.push_back({manager.add_mesh_asset(std::move(asset)), 0, Transform{}});
  scene.lights.push_back({glm::vec3(0.0f), glm::vec3(1.0f), 1.0f, std::nullopt, assets::LightKind::Directional, glm::vec3(0, -0.8f, -0.6f)});
  scene.views.push_back({"front", glm::vec3(0.0f, 0.0f, 3.0f), 0.0f, 0.0f});
  WorldOptions options;
  options.mode = mode;
  options.size = kSize;
  World world(std::move(manager), std::move(scene), options);
  world.frame(0.0);
  return world.renderer().read_output();
}

// A 4x4 normal map whose every texel holds the tangent-space normal (0, g, z)
// with green encoded as `green` (0..255): RGBA8, or BC5 (red and green blocks,
// both endpoints the value, every index 0).
assets::TextureData constant_normal_map(std::uint8_t green, bool bc5) {
  assets::TextureData texture;
  texture.name = bc5 ? "bc5 normal" : "rgba normal";
  if (bc5) {
    texture.compressed = assets::CompressedImage{assets::BlockFormat::BC5, 4, 4, {{128, 128, 0, 0, 0, 0, 0, 0, green, green, 0, 0, 0, 0, 0, 0}}};
  } else {
    const float g = green / 255.0f * 2.0f - 1.0f;
    const auto z = static_cast<std::uint8_t>(std::lround((std::sqrt(1.0f - g * g) * 0.5f + 0.5f) * 255.0f));
    texture.image = assets::Image{4, 4, {}};
    for (int i = 0; i < 16; ++i) texture.image.rgba.insert(texture.image.rgba.end(), {128, green, z, 255});
  }
  return texture;
}

TEST_F(ModelRender, NormalMapsTiltAlikeInEveryEncodingAndConvention) {
  // The normal tilted 37 degrees along the map's green axis: 204 in OpenGL's
  // convention, 51 in DirectX's (green down).
  constexpr std::uint8_t kUp = 204, kDown = 51;
  for (const std::string& mode : {std::string("forward"), std::string("deferred"), std::string("clustered-deferred")}) {
    const assets::Image flat = normal_mapped_quad(std::nullopt, false, mode);
    const assets::Image reference = normal_mapped_quad(constant_normal_map(kUp, false), false, mode);
    const double centre = assets::luma(reference, kSize.x / 2, kSize.y / 2);
    assets::write_png("model_normal_" + mode + ".png", reference);
    EXPECT_GT(std::abs(centre - assets::luma(flat, kSize.x / 2, kSize.y / 2)), 0.08) << mode << ": the normal map changes the shading";
    const std::pair<assets::Image, std::string> same[] = {
        {normal_mapped_quad(constant_normal_map(kDown, false), true, mode), "RGBA, DirectX, flagged"},
        {normal_mapped_quad(constant_normal_map(kUp, true), false, mode), "BC5, OpenGL"},
        {normal_mapped_quad(constant_normal_map(kDown, true), true, mode), "BC5, DirectX, flagged"},
    };
    for (const auto& [image, what] : same) EXPECT_GE(assets::psnr(reference, image), kMinimumPsnr) << mode << " " << what;
    const assets::Image unflagged = normal_mapped_quad(constant_normal_map(kDown, false), false, mode);
    EXPECT_GT(std::abs(centre - assets::luma(unflagged, kSize.x / 2, kSize.y / 2)), 0.1)
        << mode << ": a DirectX map read as OpenGL's tilts the other way";
  }
}

}  // namespace
}  // namespace atrium
