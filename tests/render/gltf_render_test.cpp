// What users see of files other tools wrote: each compressed fixture
// (tests/data/gltf-tools) draws its source's picture; unlit surfaces and vertex
// colours draw their colours exactly in every mode and shading model; a model
// from 1 cm to 10 km draws the same picture from its auto-framed views in every
// mode; a flat model is never seen edge-on; Blender's glass draws forward's
// picture in every mode.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/cli.hpp"
#include "app/world.hpp"
#include "assets/gltf_import.hpp"
#include "assets/image.hpp"
#include "assets/mesh_builder.hpp"
#include "assets/scene_file.hpp"
#include "support/adopt_views.hpp"
#include "support/gl_test.hpp"
#include "support/modes.hpp"
#include "support/reference_shading.hpp"
#include "render/lighting/shading_model.hpp"

namespace atrium {
namespace {
namespace fs = std::filesystem;

using testing::kSize;
const fs::path kFixtures = fs::path(ATRIUM_SOURCE_DIR) / "tests/data/gltf-tools";
const fs::path kBlender = fs::path(ATRIUM_TESTDATA_DIR) / "gltf/blender-exports";

using GltfRender = testing::GlTest;

// A model's scene with the views and lights of `like` (its source's), so that
// both draw from the same cameras under the same lights.
assets::SceneDescription model_scene(const fs::path& path, assets::AssetManager& assets, const assets::SceneDescription* like) {
  assets::LoadReport report;
  assets::SceneDescription scene = assets::load_model_scene(path, assets, 24, report);
  if (like) testing::adopt_views_and_lights(scene, *like);
  return scene;
}

std::vector<assets::Image> render_views(assets::AssetManager assets, assets::SceneDescription scene, const std::string& mode,
                                        int views, const std::string& shading = "pbr") {
  WorldOptions options;
  options.mode = mode;
  options.size = kSize;
  options.shading = shading;
  World world(std::move(assets), std::move(scene), options);
  std::vector<assets::Image> images;
  for (int view = 1; view <= views; ++view) {
    world.set_view(view);
    world.frame(0.0);
    images.push_back(world.renderer().read_output());
  }
  return images;
}

TEST_F(GltfRender, EveryToolWrittenFixtureDrawsItsSourcesPicture) {
  std::size_t compared = 0;
  for (const auto& entry : fs::directory_iterator(kFixtures)) {
    const std::string name = entry.path().filename().string();
    // Conversions are named model.tool.glb; model.glb is an original Blender wrote.
    if (entry.path().extension() != ".glb" || entry.path().stem().string().find('.') == std::string::npos) continue;
    const std::string model = name.substr(0, name.find('.'));
    const fs::path source = model == "blender-colors" ? kFixtures / "blender-colors.glb" : kBlender / (model + ".gltf");
    assets::AssetManager source_assets, fixture_assets;
    const assets::SceneDescription source_scene = model_scene(source, source_assets, nullptr);
    const assets::SceneDescription fixture_scene = model_scene(entry.path(), fixture_assets, &source_scene);
    const auto expected = render_views(std::move(source_assets), source_scene, "forward", 4);
    const auto actual = render_views(std::move(fixture_assets), fixture_scene, "forward", 4);
    for (std::size_t v = 0; v < expected.size(); ++v) {
      assets::write_png("gltf_tools_" + name + "_view" + std::to_string(v + 1) + ".png", actual[v]);
      EXPECT_GE(assets::psnr(expected[v], actual[v]), kMinimumPsnr) << name << " view " << v + 1;
    }
    ++compared;
  }
  EXPECT_GE(compared, 20u);
}

// A quad facing the camera that fills the view, its corners coloured by
// COLOR_0 (red, green, blue, white from the bottom left, counter-clockwise
// from the bottom right: the two triangles share the diagonal from red to
// white), under a material that is unlit (or a lit dielectric), with lights.
assets::SceneDescription coloured_quad(assets::AssetManager& manager, bool unlit, glm::vec4 base_color) {
  assets::MeshAsset asset;
  assets::Material material;
  material.base_color_factor = base_color;
  material.unlit = unlit;
  material.metallic_factor = 0.0f;
  material.roughness_factor = 0.8f;
  // Unlit surfaces ignore emission; lit ones would show it.
  if (unlit) material.emissive_factor = glm::vec3(0.5f);
  asset.materials.push_back(material);
  assets::Geometry quad = assets::shapes::grid(glm::vec3(-4, -3, 0), glm::vec3(8, 0, 0), glm::vec3(0, 6, 0), 1, 1, 1.0f);
  const std::array<std::uint16_t, 4> colours[] = {{65535, 0, 0, 65535}, {0, 65535, 0, 65535}, {0, 0, 65535, 65535}, {65535, 65535, 65535, 65535}};
  for (std::size_t i = 0; i < quad.vertices.size(); ++i) quad.vertices[i].color = colours[i];
  asset.meshes.push_back({"quad", {assets::add_geometry(asset, std::move(quad), 0)}});
  assets::SceneDescription scene;
  scene.instances.push_back({manager.add_mesh_asset(std::move(asset)), 0, Transform{}});
  for (int i = 0; i < 12; ++i) {
    scene.lights.push_back({glm::vec3(-3.0f + 0.5f * static_cast<float>(i), 0.5f * static_cast<float>(i % 3), 1.0f), glm::vec3(1.0f), 2.0f, 4.0f});
  }
  scene.lights.push_back({glm::vec3(0.0f), glm::vec3(1.0f), 1.0f, std::nullopt, assets::LightKind::Directional, glm::vec3(0, 0, -1)});
  scene.views.push_back({"front", glm::vec3(0.0f, 0.0f, 3.0f), 0.0f, 0.0f});
  scene.bounds.add(glm::vec3(-4, -3, 0));
  scene.bounds.add(glm::vec3(4, 3, 0));
  scene.exposure = 1.0f;
  return scene;
}

TEST_F(GltfRender, UnlitSurfacesDrawTheirBaseColourTimesVertexColourInEveryModeAndShadingModel) {
  const glm::vec4 base(0.9f, 0.6f, 0.3f, 1.0f);
  // The quad's centre lies on the diagonal halfway from the red corner to the white one.
  const glm::vec3 centre_colour = glm::vec3(base) * glm::vec3(1.0f, 0.5f, 0.5f);
  std::uint8_t expected[3];
  for (int c = 0; c < 3; ++c) expected[c] = static_cast<std::uint8_t>(std::lround(testing::reference_tonemap_to_srgb(centre_colour[c]) * 255.0));
  for (const std::string& shading : {"pbr", "blinn-phong", "phong"}) {
    for (const std::string& mode : techniques::mode_names()) {
      for (const auto layout : testing::gbuffer_layouts()) {
        assets::AssetManager manager;
        assets::SceneDescription scene = coloured_quad(manager, true, base);
        WorldOptions options;
        options.mode = mode;
        options.size = kSize;
        options.shading = shading;
        options.technique_options = testing::with_layout(layout);
        World world(std::move(manager), std::move(scene), options);
        world.frame(0.0);
        const assets::Image image = world.renderer().read_output();
        const std::size_t centre = (static_cast<std::size_t>(kSize.y / 2) * kSize.x + kSize.x / 2) * 4;
        for (int c = 0; c < 3; ++c) {
          EXPECT_NEAR(image.rgba[centre + static_cast<std::size_t>(c)], expected[c], 2)
              << mode << " " << testing::test_name(mode, layout) << " " << shading << " channel " << c;
        }
      }
    }
  }
}

TEST_F(GltfRender, VertexColoursTintLitSurfacesToo) {
  assets::AssetManager manager;
  assets::SceneDescription scene = coloured_quad(manager, false, glm::vec4(1.0f));
  const auto lit = render_views(std::move(manager), std::move(scene), "forward", 1).at(0);
  assets::write_png("gltf_vertex_colours_lit.png", lit);
  // The corner whose vertex colour is red stays red under white lights.
  const auto pixel = [&](int x, int y) { return &lit.rgba[(static_cast<std::size_t>(y) * kSize.x + static_cast<std::size_t>(x)) * 4]; };
  const std::uint8_t* bottom_left = pixel(2, kSize.y - 3);
  EXPECT_GT(bottom_left[0], bottom_left[1] + 40);
  EXPECT_GT(bottom_left[0], bottom_left[2] + 40);
}

// The torus knot placed at `scale` by a scene file, lit by a directional light
// (no falloff: the picture does not depend on units), from the auto-framed views.
std::vector<assets::Image> scaled_knot(double scale, const std::string& mode) {
  const fs::path file = fs::temp_directory_path() / ("atrium_scaled_knot_" + std::to_string(::getpid()) + ".json");
  std::ofstream(file) << nlohmann::json{
      {"models", {{{"path", (kBlender / "torusknot.gltf").string()}, {"scale", scale}}}},
      {"lights", {{{"type", "directional"}, {"direction", {-0.4, -1.0, -0.6}}, {"intensity", 2.0}, {"color", {1.0, 0.95, 0.9}}}}},
      {"ambient", {0.1, 0.1, 0.1}}}.dump();
  assets::AssetManager assets;
  assets::LoadReport report;
  assets::SceneDescription scene = assets::load_scene_file(file, assets, report);
  fs::remove(file);
  return render_views(std::move(assets), std::move(scene), mode, 4);
}

TEST_F(GltfRender, AModelFromOneCentimetreToTenKilometresDrawsTheSamePictureInEveryMode) {
  // The knot is 50 m across: 0.0002 makes it 1 cm, 200 makes it 10 km.
  const auto reference = scaled_knot(1.0, "forward");
  for (std::size_t v = 0; v < reference.size(); ++v) {
    int covered = 0;
    for (int i = 0; i < kSize.x * kSize.y; ++i) covered += reference[v].rgba[static_cast<std::size_t>(i) * 4] > 10;
    EXPECT_GT(covered, kSize.x * kSize.y / 10) << "view " << v + 1 << " shows the knot";
  }
  for (const double scale : {0.0002, 0.01, 200.0, 1000.0}) {
    for (const std::string& mode : techniques::mode_names()) {
      const auto images = scaled_knot(scale, mode);
      for (std::size_t v = 0; v < images.size(); ++v) {
        assets::write_png("gltf_scaled_knot_" + std::to_string(scale) + "_" + mode + "_view" + std::to_string(v + 1) + ".png", images[v]);
        EXPECT_GE(assets::psnr(reference[v], images[v]), kMinimumPsnr) << "scale " << scale << " " << mode << " view " << v + 1;
      }
    }
  }
}

TEST_F(GltfRender, BlendersGlassDrawsForwardsPictureInEveryMode) {
  // Tinted panes (alphaMode BLEND, written by Blender) over blocks, over each
  // other and against the sky; 16 lights. The tiled and clustered modes shade
  // them from their own light lists, the others over every light.
  const fs::path file = kFixtures / "blender-glass.glb";
  auto scene_of = [&](assets::AssetManager& assets) {
    assets::SceneDescription scene = model_scene(file, assets, nullptr);
    std::size_t blended = 0;
    for (const assets::Material& m : assets.mesh_asset(scene.instances.at(0).asset).materials) {
      blended += m.alpha_mode == assets::AlphaMode::Blend;
    }
    EXPECT_EQ(blended, 4u) << "Blender wrote the four panes as alphaMode BLEND";
    return scene;
  };
  assets::AssetManager reference_assets;
  const assets::SceneDescription reference_scene = scene_of(reference_assets);
  const auto reference = render_views(std::move(reference_assets), reference_scene, "forward", 4);
  for (const std::string& mode : testing::non_forward_modes()) {
    assets::AssetManager assets;
    const assets::SceneDescription scene = scene_of(assets);
    const auto images = render_views(std::move(assets), scene, mode, 4);
    for (std::size_t v = 0; v < images.size(); ++v) {
      assets::write_png("gltf_glass_" + mode + "_view" + std::to_string(v + 1) + ".png", images[v]);
      EXPECT_GE(assets::psnr(reference[v], images[v]), kMinimumPsnr) << mode << " view " << v + 1;
    }
  }
}

TEST_F(GltfRender, MirroredInstancesKeepTheirFrontFaces) {
  // glTF: a node whose transform has a negative determinant turns its
  // triangles' winding, so clockwise ones face forwards (as Blender writes
  // mirrored objects; subpass_scene_opaque.gltf has dozens).
  auto render = [&](glm::vec3 scale) {
    assets::AssetManager manager;
    assets::MeshAsset asset;
    assets::Material material;  // single-sided: back faces are culled
    material.metallic_factor = 0.0f;
    asset.materials.push_back(material);
    asset.meshes.push_back({"quad", {assets::add_geometry(asset, assets::shapes::grid(glm::vec3(-2, -1.5f, 0), glm::vec3(4, 0, 0),
                                                                                       glm::vec3(0, 3, 0), 2, 2, 1.0f), 0)}});
    assets::SceneDescription scene;
    Transform transform;
    transform.scale = scale;
    scene.instances.push_back({manager.add_mesh_asset(std::move(asset)), 0, transform});
    scene.lights.push_back({glm::vec3(0.0f), glm::vec3(1.0f), 1.5f, std::nullopt, assets::LightKind::Directional, glm::vec3(0, 0, -1)});
    scene.views.push_back({"front", glm::vec3(0.0f, 0.0f, 3.0f), 0.0f, 0.0f});
    return render_views(std::move(manager), std::move(scene), "deferred", 1).at(0);
  };
  const assets::Image plain = render(glm::vec3(1.0f));
  const assets::Image mirrored = render(glm::vec3(-1.0f, 1.0f, 1.0f));
  assets::write_png("gltf_mirrored.png", mirrored);
  EXPECT_GT(assets::luma(plain, kSize.x / 2, kSize.y / 2), 0.3);
  EXPECT_GE(assets::psnr(plain, mirrored), kMinimumPsnr) << "the mirrored quad is drawn, lit from the front";
}

TEST_F(GltfRender, FlatModelsAreNeverSeenEdgeOn) {
  // A floor plate (XZ) and a wall of signs (XY), each with no thickness.
  for (const auto& [edge_u, edge_v] : {std::pair{glm::vec3(6, 0, 0), glm::vec3(0, 0, -4)}, std::pair{glm::vec3(6, 0, 0), glm::vec3(0, 4, 0)},
                                       std::pair{glm::vec3(0, 0, -6), glm::vec3(0, 4, 0)}}) {
    assets::AssetManager manager;
    assets::MeshAsset asset;
    assets::Material material;
    material.double_sided = true;
    material.unlit = true;
    asset.materials.push_back(material);
    asset.meshes.push_back({"plate", {assets::add_geometry(asset, assets::shapes::grid(glm::vec3(0), edge_u, edge_v, 4, 4, 1.0f), 0)}});
    assets::SceneDescription scene;
    scene.instances.push_back({manager.add_mesh_asset(std::move(asset)), 0, Transform{}});
    scene.bounds.add(glm::vec3(0));
    scene.bounds.add(edge_u + edge_v);
    scene.views = assets::framing_views(scene.bounds);
    const auto images = render_views(std::move(manager), std::move(scene), "forward", 5);
    for (std::size_t v = 0; v < images.size(); ++v) {
      assets::write_png("gltf_flat_" + std::to_string(static_cast<int>(edge_u.x)) + std::to_string(static_cast<int>(edge_v.y)) + "_view" +
                            std::to_string(v + 1) + ".png",
                        images[v]);
      int covered = 0;
      for (int i = 0; i < kSize.x * kSize.y; ++i) covered += images[v].rgba[static_cast<std::size_t>(i) * 4] > 100;
      EXPECT_GT(covered, kSize.x * kSize.y / 12) << "plate " << edge_u.x << "," << edge_v.y << " view " << v + 1;
    }
  }
}

}  // namespace
}  // namespace atrium
