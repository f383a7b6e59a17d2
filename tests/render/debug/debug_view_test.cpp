// Debug views: each renders something, each differs from the others, the
// heatmap's counts are the light evaluations each mode really performs, and the
// light-lists and depth-slices views show the bins the tiled and clustered
// modes really built (checked against the lists read back and a CPU slicing).
#include <cmath>
#include <map>
#include <set>

#include "app/world.hpp"
#include "assets/image.hpp"
#include "assets/mesh_builder.hpp"
#include "components/frame_resources.hpp"
#include "render/frame/frame_modules.hpp"
#include "support/gl_test.hpp"
#include "render/techniques/clustered/clustered.hpp"
#include "render/debug/debug_views.hpp"
#include "render/techniques/tiled/tiled.hpp"

namespace atrium {
namespace {

using testing::kSize;

using DebugViewRender = testing::GlTest;

TEST_F(DebugViewRender, EveryViewRendersNonBlankAndDistinct) {
  // Clustered deferred has a G-buffer and light lists, and with shadows on an
  // atlas: every view but a mode's own (the visibility buffer's) has something
  // to show there; those are drawn in the first mode that offers them.
  World world({.scene = "atrium", .lights = 48u, .mode = "clustered-deferred", .size = kSize});
  world.registry().resource<RendererSettings>().shadows = 8;
  std::vector<assets::Image> images;
  std::vector<std::string_view> names;
  for (const render::DebugView& row : render::debug_view_table()) {
    const std::string_view name = row.name;
    names.push_back(name);
    world.registry().resource<RendererSettings>().debug_view.clear();
    world.set_mode("clustered-deferred");
    world.frame(0.0);
    for (const std::string& mode : techniques::mode_names()) {
      if (world.renderer().offers(name)) break;
      world.set_mode(mode);
      world.frame(0.0);
    }
    // A view no mode offers without options of its own (msaa-edges) is drawn in clustered-deferred.
    if (!world.renderer().offers(name)) world.set_mode("clustered-deferred");
    world.registry().resource<RendererSettings>().debug_view = std::string(name);
    world.frame(0.0);
    world.frame(0.0);  // past the first frame's list growth
    images.push_back(world.renderer().read_output());
    assets::write_png("debug_view_" + std::string(name) + ".png", images.back());
    int lit = 0;
    for (int y = 0; y < kSize.y; ++y) {
      for (int x = 0; x < kSize.x; ++x) lit += assets::luma(images.back(), x, y) > 0.02;
    }
    // Emission covers only the lamps, specular light the highlights (a dielectric
    // reflects 4% head-on); everything else fills most of the view.
    const int least = name == "emissive" ? 10 : name == "specular-light" ? kSize.x * kSize.y / 100 : kSize.x * kSize.y / 3;
    EXPECT_GT(lit, least) << name;
  }
  for (std::size_t a = 0; a < images.size(); ++a) {
    for (std::size_t b = a + 1; b < images.size(); ++b) {
      EXPECT_LT(assets::psnr(images[a], images[b]), 30.0) << names[a] << " vs " << names[b];
    }
  }
  world.registry().resource<RendererSettings>().debug_view.clear();
  world.frame(0.0);
}

double coverage(World& world) {
  const std::vector<float> depth = world.renderer().read_view_depth();
  double covered = 0;
  for (float d : depth) covered += std::isfinite(d);
  return covered / static_cast<double>(depth.size());
}

double evaluations(World& world, const char* mode) {
  world.set_mode(mode);
  world.frame(0.0);
  world.renderer().settle();
  return world.renderer().stats().light_evaluations_per_pixel;
}

// Three quads that each cover the whole view, one behind the other: every
// geometry pass rasterises each pixel three times.
World stacked_quads(const std::string& mode) {
  assets::AssetManager manager;
  assets::MeshAsset asset;
  assets::Material material;
  material.metallic_factor = 0.0f;
  asset.materials.push_back(material);
  std::vector<assets::Primitive> quads;
  for (int i = 0; i < 3; ++i) {
    const float z = -1.0f - static_cast<float>(i);
    quads.push_back(assets::add_geometry(
        asset, assets::shapes::grid(glm::vec3(-40, -30, z), glm::vec3(80, 0, 0), glm::vec3(0, 60, 0), 1, 1, 1.0f), 0));
  }
  asset.meshes.push_back({"quads", quads});
  assets::SceneDescription scene;
  scene.instances.push_back({manager.add_mesh_asset(std::move(asset)), 0, Transform{}});
  scene.lights.push_back({glm::vec3(0, 0, 2), glm::vec3(1.0f), 1.0f, 50.0f});
  scene.views.push_back({"front", glm::vec3(0.0f, 0.0f, 3.0f), 0.0f, 0.0f});
  return World(std::move(manager), std::move(scene), {.scene = "", .mode = mode, .size = kSize});
}

TEST_F(DebugViewRender, FragmentsViewCountsWhatEachGeometryPassRasterises) {
  // Forward and the G-buffer modes rasterise the scene once; clustered forward
  // twice (its depth pre-pass, then its shading pass).
  // The light pre-pass twice too (its thin G-buffer, then its material pass).
  for (const auto& [mode, passes] : {std::pair{"forward", 1}, std::pair{"deferred", 1}, std::pair{"clustered-forward", 2},
                                     std::pair{"light-volumes", 1}, std::pair{"light-prepass", 2}}) {
    World world = stacked_quads(mode);
    world.registry().resource<RendererSettings>().debug_view = "fragments";
    world.frame(0.0);
    world.renderer().settle();
    EXPECT_DOUBLE_EQ(world.renderer().stats().fragments_per_pixel, 3.0 * passes) << mode;
    // The driver's own count per pass (pipeline statistics) includes the helper
    // invocations of 2x2 quads, so it is at least the fragments rasterised.
    const gfx::PassTimer& timer = world.renderer().timer();
    if (!timer.counts_fragments()) continue;
    std::uint64_t shaded = 0, tonemap = 0;
    for (const gfx::PassTime& pass : timer.latest()) {
      if (pass.name == "tonemap") tonemap = pass.fragments;
      else shaded += pass.fragments;
    }
    EXPECT_GE(tonemap, static_cast<std::uint64_t>(kSize.x * kSize.y)) << mode;
    EXPECT_GE(shaded, static_cast<std::uint64_t>(3 * passes * kSize.x * kSize.y)) << mode;
  }
}

TEST_F(DebugViewRender, HeatmapCountsWhatEachModeEvaluates) {
  constexpr std::uint32_t kLights = 40;
  World world({.scene = "atrium", .lights = kLights, .mode = "deferred", .size = kSize});
  world.registry().resource<RendererSettings>().debug_view = "heatmap";
  const double deferred = evaluations(world, "deferred");
  // Deferred evaluates every light once for every covered pixel, exactly.
  world.registry().resource<RendererSettings>().debug_view.clear();
  world.frame(0.0);
  const double covered = coverage(world);
  world.registry().resource<RendererSettings>().debug_view = "heatmap";
  EXPECT_NEAR(deferred, kLights * covered, 1e-9);
  const double radius = evaluations(world, "deferred-radius");
  const double volumes = evaluations(world, "light-volumes");
  const double instanced = evaluations(world, "light-volumes-instanced");
  const double forward = evaluations(world, "forward");
  EXPECT_LT(radius, deferred * 0.9) << "radius culling skips lights";
  // The stencil finds the pixels inside each volume's mesh, which circumscribes
  // the sphere: the same pixels as the radius test, plus a thin shell.
  EXPECT_GE(volumes, radius);
  EXPECT_LE(volumes, radius * 1.1);
  EXPECT_GE(instanced, volumes) << "without the stencil, pixels in front of a sphere are shaded too";
  EXPECT_DOUBLE_EQ(evaluations(world, "light-prepass"), instanced) << "the light pre-pass sums through the same instanced volumes";
  EXPECT_GE(forward, deferred) << "forward shades overdrawn fragments too";
}

struct Rgb {
  std::uint8_t r, g, b;
  auto operator<=>(const Rgb&) const = default;
};

Rgb pixel(const assets::Image& image, int x, int y) {
  const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) + static_cast<std::size_t>(x)) * 4;
  return {image.rgba[i], image.rgba[i + 1], image.rgba[i + 2]};
}

constexpr Rgb kMagenta{255, 0, 255}, kBlack{0, 0, 0};

// The bin each covered pixel (top-down image order) reads, -1 for background,
// worked out on the CPU from the depth buffer and the technique's layout.
std::vector<int> pixel_bins(World& world) {
  const std::vector<float> depth = world.renderer().read_view_depth();
  std::vector<int> bins(depth.size(), -1);
  const techniques::LightingTechnique* technique = world.renderer().technique();
  const auto* tiled = dynamic_cast<const techniques::TiledTechnique*>(technique);
  const auto* clustered = dynamic_cast<const techniques::ClusteredTechnique*>(technique);
  for (int y = 0; y < kSize.y; ++y) {
    for (int x = 0; x < kSize.x; ++x) {
      const std::size_t i = static_cast<std::size_t>(y * kSize.x + x);
      if (!std::isfinite(depth[i])) continue;
      const int gl_y = kSize.y - 1 - y;
      if (tiled) {
        bins[i] = gl_y / techniques::kTileSize * static_cast<int>(tiled->tiles().x) + x / techniques::kTileSize;
      } else {
        const glm::uvec3 dims = clustered->grid().dims();
        const glm::uvec2 tile = glm::uvec2(glm::clamp(glm::vec2(x + 0.5f, gl_y + 0.5f) / glm::vec2(kSize) * glm::vec2(dims),
                                                      glm::vec2(0.0f), glm::vec2(dims) - 1.0f));
        bins[i] = static_cast<int>((clustered->grid().slice_of(depth[i]) * dims.y + tile.y) * dims.x + tile.x);
      }
    }
  }
  return bins;
}

std::vector<std::vector<std::uint32_t>> read_lists(World& world) {
  const techniques::LightingTechnique* technique = world.renderer().technique();
  if (const auto* tiled = dynamic_cast<const techniques::TiledTechnique*>(technique)) return tiled->list().read();
  return dynamic_cast<const techniques::ClusteredTechnique*>(technique)->grid().read_lists();
}

// Per key (a light count, a slice): the colour most of its pixels got, and how
// many pixels in all got their key's majority colour.
template <typename Key>
struct Majority {
  std::map<Key, Rgb> colour;
  int agreeing = 0;
};

template <typename Key>
Majority<Key> majority_colours(const std::map<Key, std::map<Rgb, int>>& colours) {
  Majority<Key> result;
  for (const auto& [key, seen] : colours) {
    const auto majority = std::max_element(seen.begin(), seen.end(), [](auto& a, auto& b) { return a.second < b.second; });
    result.colour[key] = majority->first;
    result.agreeing += majority->second;
  }
  return result;
}

class LightListView : public testing::GlTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(LightListView, ColoursEachPixelByItsBinsLightCount) {
  World world({.scene = "atrium", .lights = 256u, .mode = GetParam(), .size = kSize});
  world.registry().resource<RendererSettings>().debug_view = "light-lists";
  world.frame(0.0);
  world.frame(0.0);
  const assets::Image image = world.renderer().read_output();
  assets::write_png("debug_view_light_lists_" + GetParam() + ".png", image);
  const std::vector<int> bins = pixel_bins(world);
  const auto lists = read_lists(world);
  // Per light count: the colours its pixels got and their mean luma. Pixels on
  // a slice boundary may round into the neighbouring cluster: allow 2%.
  std::map<std::size_t, std::map<Rgb, int>> colours;
  std::map<std::size_t, double> luma_sum;
  int covered = 0;
  for (int y = 0; y < kSize.y; ++y) {
    for (int x = 0; x < kSize.x; ++x) {
      const int bin = bins[static_cast<std::size_t>(y * kSize.x + x)];
      if (bin < 0) continue;
      ++covered;
      const std::size_t count = lists[static_cast<std::size_t>(bin)].size();
      ++colours[count][pixel(image, x, y)];
      luma_sum[count] += assets::luma(image, x, y);
      EXPECT_NE(pixel(image, x, y), kMagenta) << "nothing overflowed in the second frame";
    }
  }
  const auto majority = majority_colours(colours);
  std::set<Rgb> used;
  double previous_luma = -1.0;
  for (const auto& [count, seen] : colours) {
    if (count == 0) EXPECT_EQ(majority.colour.at(count), kBlack) << "empty bins are black";
    EXPECT_TRUE(used.insert(majority.colour.at(count)).second) << "count " << count << " shares its colour with another count";
    int pixels = 0;
    for (const auto& entry : seen) pixels += entry.second;
    const double mean_luma = luma_sum[count] / pixels;
    if (count > 0) EXPECT_GT(mean_luma, previous_luma) << "more lights read lighter (count " << count << ")";
    previous_luma = mean_luma;
  }
  EXPECT_GE(colours.size(), 4u) << "the view spans several counts";
  EXPECT_GE(majority.agreeing, covered * 98 / 100);
}

INSTANTIATE_TEST_SUITE_P(Modes, LightListView, ::testing::Values("tiled-deferred", "clustered-deferred", "clustered-forward"),
                         [](const auto& info) {
                           std::string name = info.param;
                           for (char& c : name) if (c == '-') c = '_';
                           return name;
                         });

TEST_F(DebugViewRender, LightListViewMarksWhereLightsThatOverflowedReach) {
  World world({.scene = "atrium", .lights = 1024u, .mode = "clustered-deferred", .size = kSize, .light_radius = 0.25f});
  world.registry().resource<RendererSettings>().debug_view = "light-lists";
  auto magenta_pixels = [&] {
    const assets::Image image = world.renderer().read_output();
    int magenta = 0;
    for (int y = 0; y < kSize.y; ++y) {
      for (int x = 0; x < kSize.x; ++x) magenta += pixel(image, x, y) == kMagenta;
    }
    return magenta;
  };
  world.frame(0.0);
  world.frame(0.0);
  EXPECT_EQ(magenta_pixels(), 0);
  world.set_light_radius(4.0f);  // the lists were sized for small lights: many overflow this frame
  world.frame(0.0);
  EXPECT_GT(magenta_pixels(), 0);
  world.frame(0.0);  // the overflowed frame's total has arrived: the list grew before this one
  EXPECT_EQ(world.renderer().stats().light_list_overflows, 1u);
  EXPECT_EQ(magenta_pixels(), 0);
}

TEST_F(DebugViewRender, LightListViewIsFlatGreyInModesWithoutLists) {
  World world({.scene = "atrium", .lights = 16u, .mode = "deferred", .size = kSize});
  world.registry().resource<RendererSettings>().debug_view = "light-lists";
  world.frame(0.0);
  const assets::Image image = world.renderer().read_output();
  EXPECT_EQ(pixel(image, 0, 0), pixel(image, kSize.x / 2, kSize.y / 2));
  EXPECT_EQ(pixel(image, 0, 0), (Rgb{38, 38, 38}));
}

// What `render --debug-view list` offers is what draws: in every mode (with
// shadows on), each view the table offers shows more than flat grey, and the
// views it does not offer show flat grey (the G-buffer views fill a G-buffer
// of their own, so every mode offers them; msaa-edges is tested with MSAA in
// msaa_test.cpp).
TEST_F(DebugViewRender, EveryViewAModeOffersShowsSomethingAndTheOthersShowNothingOfTheirOwn) {
  constexpr glm::ivec2 kSmall{48, 27};
  auto flat_grey = [&](const assets::Image& image) {
    for (int y = 0; y < kSmall.y; ++y) {
      for (int x = 0; x < kSmall.x; ++x) {
        if (pixel(image, x, y) != (Rgb{38, 38, 38})) return false;
      }
    }
    return true;
  };
  int offered_somewhere = 0;
  for (const std::string& mode : techniques::mode_names()) {
    World world({.scene = "atrium", .lights = 32u, .mode = mode, .size = kSmall, .shadows = 2});
    world.frame(0.0);
    auto& settings = world.registry().resource<RendererSettings>();
    for (const render::DebugView& view : render::debug_view_table()) {
      const bool offered = world.renderer().offers(view.name);
      offered_somewhere += offered;
      settings.debug_view = std::string(view.name);
      world.frame(0.0);
      const bool grey = flat_grey(world.renderer().read_output());
      if (offered) EXPECT_FALSE(grey) << mode << " offers " << view.name << " but draws flat grey";
      if (!offered && (view.name == "light-lists" || view.name == "light-buffer" || view.name == "diffuse-light" ||
                       view.name == "specular-light" || view.name == "shadow-atlas")) {
        EXPECT_TRUE(grey) << mode << " does not offer " << view.name << " but draws something for it";
      }
    }
  }
  EXPECT_GT(offered_somewhere, 9 * 10) << "most views in most modes";
}

// The light-sum views and thumbnails: grey until a deferred mode writes the sums
// apart (forward modes never do), the sums once it does.
TEST_F(DebugViewRender, LightSumViewsAndThumbnailsShowTheSplitOfDeferredModesOnly) {
  World world({.scene = "atrium", .lights = 48u, .mode = "forward", .size = kSize});
  auto& settings = world.registry().resource<RendererSettings>();
  for (const char* view : {"diffuse-light", "specular-light"}) {
    settings.debug_view = view;
    world.frame(0.0);
    const assets::Image image = world.renderer().read_output();
    EXPECT_EQ(pixel(image, 0, 0), (Rgb{38, 38, 38})) << view;
    EXPECT_EQ(pixel(image, kSize.x / 2, kSize.y / 2), (Rgb{38, 38, 38})) << view;
  }
  settings.debug_view.clear();
  settings.gbuffer_thumbnails = true;
  world.set_mode("tiled-deferred");
  // Each thumbnail cell's set of colours, cells in kThumbnailViews order.
  auto cell_colours = [&] {
    const GLuint texture = world.renderer().gbuffer_thumbnails();
    const glm::ivec2 cell = world.renderer().thumbnail_size();
    constexpr int kColumns = render::DebugViews::kThumbnailColumns, kRows = render::DebugViews::kThumbnailCount / kColumns;
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(cell.x * kColumns * cell.y * kRows) * 4);
    glGetTextureImage(texture, 0, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(rgba.size()), rgba.data());
    std::vector<std::set<Rgb>> colours(render::DebugViews::kThumbnailCount);
    for (int index = 0; index < render::DebugViews::kThumbnailCount; ++index) {
      const int column = index % kColumns, row = kRows - 1 - index / kColumns;  // GL rows run bottom-up
      for (int y = row * cell.y; y < (row + 1) * cell.y; ++y) {
        for (int x = column * cell.x; x < (column + 1) * cell.x; ++x) {
          const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(cell.x * kColumns) + static_cast<std::size_t>(x)) * 4;
          colours[static_cast<std::size_t>(index)].insert(Rgb{rgba[i], rgba[i + 1], rgba[i + 2]});
        }
      }
    }
    return colours;
  };
  world.frame(0.0);
  auto colours = cell_colours();
  EXPECT_EQ(colours[6], (std::set<Rgb>{{38, 38, 38}})) << "diffuse thumbnail without the split";
  EXPECT_EQ(colours[7], (std::set<Rgb>{{38, 38, 38}})) << "specular thumbnail without the split";
  EXPECT_GT(colours[2].size(), 100u) << "albedo thumbnail";
  settings.technique_options.split_lighting = true;
  world.frame(0.0);
  colours = cell_colours();
  EXPECT_GT(colours[6].size(), 100u) << "diffuse thumbnail with the split";
  EXPECT_GT(colours[7].size(), 20u) << "specular thumbnail with the split";
  EXPECT_NE(colours[6], colours[7]);
}

// The light pre-pass shows its own thin G-buffer (what it does not store is
// grey) and its light buffer; modes without a light buffer show grey there.
TEST_F(DebugViewRender, LightPrepassShowsItsThinGBufferAndLightBuffer) {
  World world({.scene = "atrium", .lights = 48u, .mode = "deferred", .size = kSize});
  auto& settings = world.registry().resource<RendererSettings>();
  auto colours_of = [](const assets::Image& image) {
    std::set<Rgb> colours;
    for (int y = 0; y < image.height; ++y) {
      for (int x = 0; x < image.width; ++x) colours.insert(pixel(image, x, y));
    }
    return colours;
  };
  auto view = [&](const char* name) {
    settings.debug_view = name;
    world.frame(0.0);
    return world.renderer().read_output();
  };
  EXPECT_EQ(colours_of(view("light-buffer")), (std::set<Rgb>{{38, 38, 38}})) << "deferred keeps no light buffer";
  const assets::Image deferred_normal = view("normal");
  world.set_mode("light-prepass");
  const assets::Image light_buffer = view("light-buffer");
  assets::write_png("debug_view_light_prepass_light_buffer.png", light_buffer);
  EXPECT_GT(colours_of(light_buffer).size(), 200u);
  // The light buffer holds light before albedo: it is not the lit image.
  settings.debug_view.clear();
  world.frame(0.0);
  EXPECT_LT(assets::psnr(light_buffer, world.renderer().read_output()), 25.0);
  // Normals: 16 bits in both G-buffers, so the same picture.
  EXPECT_GE(assets::psnr(deferred_normal, view("normal")), 50.0);
  for (const char* grey : {"albedo", "emissive"}) {
    EXPECT_EQ(colours_of(view(grey)), (std::set<Rgb>{{0, 0, 0}, {38, 38, 38}})) << grey << ": background and grey";
  }
  settings.debug_view.clear();
  settings.gbuffer_thumbnails = true;
  world.frame(0.0);
  EXPECT_NE(world.renderer().gbuffer_thumbnails(), 0u) << "the thin G-buffer has thumbnails";
}

// Each --z-slicing scheme in a mode with a grid and in one without.
TEST_F(DebugViewRender, DepthSlicesMatchTheCpuSlicingInAnyModeAndScheme) {
  for (const char* mode : {"forward", "clustered-deferred"}) {
    for (std::size_t scheme = 0; scheme < kZSlicingNames.size(); ++scheme) {
      const auto slicing = static_cast<ZSlicing>(scheme);
      const std::string label = std::string(mode) + "/" + std::string(kZSlicingNames[scheme]);
      World world({.scene = "atrium", .lights = 16u, .mode = mode, .size = kSize});
      world.registry().resource<RendererSettings>().debug_view = "depth-slices";
      world.registry().resource<RendererSettings>().technique_options.z_slicing = slicing;
      world.frame(0.0);
      const assets::Image image = world.renderer().read_output();
      assets::write_png("debug_view_depth_slices_" + std::string(mode) + "_" + std::string(kZSlicingNames[scheme]) + ".png",
                        image);
      const std::vector<float> depth = world.renderer().read_view_depth();
      lighting::ClusterGrid grid(TechniqueOptions{}.cluster_grid.at(kSize), slicing);
      const auto& view = world.registry().resource<ViewState>();
      grid.update(view.projection, view.near_plane, view.far_plane);
      std::map<std::uint32_t, std::map<Rgb, int>> colours;
      int covered = 0;
      for (int y = 0; y < kSize.y; ++y) {
        for (int x = 0; x < kSize.x; ++x) {
          const float d = depth[static_cast<std::size_t>(y * kSize.x + x)];
          if (!std::isfinite(d)) continue;
          ++covered;
          ++colours[grid.slice_of(d)][pixel(image, x, y)];
        }
      }
      EXPECT_GE(colours.size(), 4u) << label << ": the view spans several slices";
      const auto majority = majority_colours(colours);
      std::set<Rgb> used;
      for (const auto& [slice, colour] : majority.colour) {
        EXPECT_TRUE(used.insert(colour).second) << label << ": slice " << slice << " shares its colour";
      }
      EXPECT_GE(majority.agreeing, covered * 98 / 100) << label;
    }
  }
}

// Every resource a mode's graph declares viewable is a view of its own name
// (the light pre-pass's light-buffer targets, the tiled and clustered lists,
// forward+'s MSAA shading depth, the HDR image), drawn by its kind's
// visualiser: something in every one, never the flat grey of nothing.
TEST_F(DebugViewRender, EveryResourceViewOfEveryModeDraws) {
  constexpr glm::ivec2 kSmall{48, 27};
  std::set<std::string> seen;
  for (const std::string& mode : techniques::mode_names()) {
    for (const int msaa : {1, 4}) {
      TechniqueOptions options;
      options.msaa = msaa;
      if (!techniques::refusal(*techniques::find_technique(mode), options).empty()) continue;
      World world({.scene = "atrium", .lights = 32u, .mode = mode, .size = kSmall, .technique_options = options});
      world.frame(0.0);
      auto& settings = world.registry().resource<RendererSettings>();
      std::vector<std::string> resource_views;
      for (const render::OfferedView& view : world.renderer().offered_views()) {
        if (!render::find_debug_view(view.name)) resource_views.push_back(view.name);
      }
      EXPECT_FALSE(resource_views.empty()) << mode << ": the HDR image at least";
      for (const std::string& name : resource_views) {
        seen.insert(name);
        settings.debug_view = name;
        world.frame(0.0);
        world.frame(0.0);
        const assets::Image image = world.renderer().read_output();
        std::set<Rgb> colours;
        for (int y = 0; y < kSmall.y; ++y) {
          for (int x = 0; x < kSmall.x; ++x) colours.insert(pixel(image, x, y));
        }
        EXPECT_GT(colours.size(), 4u) << mode << " (" << msaa << "x) view " << name << " shows nothing";
      }
      settings.debug_view.clear();
    }
  }
  for (const char* name : {"hdr", "tile-light-lists", "cluster-light-lists", "light-buffer.diffuse", "light-buffer.specular-f0",
                           "light-buffer.specular", "shading-depth"}) {
    EXPECT_TRUE(seen.contains(name)) << name << " was never offered";
  }
}

// A target any contributor declares with a view kind is a view under its name
// with no edit to the debug views: the way a new technique's targets become
// viewable. Here a pass after lighting fills a colour target of its own with a
// known colour; the view shows it tone-mapped, and a name no graph declares is
// refused with the views it could have been.
TEST_F(DebugViewRender, ATargetAContributorDeclaresIsAViewByItsName) {
  World world({.scene = "atrium", .lights = 8u, .mode = "deferred", .size = {32, 18}});
  world.registry().resource<render::FrameModules>().add({render::FrameStage::AfterLighting, "test fill", [](render::FrameBuild& build) {
    render::FrameGraph& graph = build.graph;
    graph.add_pass("test fill", [&](render::PassBuilder& pass) {
      pass.keep();
      pass.create("test-fill", render::TextureDesc{GL_RGBA16F, build.targets.size, 1}, render::ViewKind::Color);
    }, [&graph](const render::PassResources& res) {
      const GLfloat colour[] = {0.0f, 4.0f, 0.0f, 1.0f};
      glClearTexImage(res.texture(graph.find("test-fill")), 0, GL_RGBA, GL_FLOAT, colour);
    });
  }, {}});
  world.frame(0.0);
  EXPECT_TRUE(world.renderer().offers("test-fill"));
  world.registry().resource<RendererSettings>().debug_view = "test-fill";
  world.frame(0.0);
  const assets::Image image = world.renderer().read_output();
  const Rgb centre = pixel(image, 16, 9);
  EXPECT_EQ(centre.r, 0);
  EXPECT_GT(centre.g, 200) << "bright green, tone-mapped";
  EXPECT_EQ(centre.b, 0);
  world.registry().resource<RendererSettings>().debug_view = "test-fil";
  try {
    world.frame(0.0);
    ADD_FAILURE() << "an unknown view was drawn";
  } catch (const render::UnknownViewError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown debug view 'test-fil' (views: position, normal"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("test-fill"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace atrium
