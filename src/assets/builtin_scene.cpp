#include "assets/builtin_scene.hpp"

#include <array>
#include <cmath>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "assets/mesh_builder.hpp"
#include "assets/procedural_textures.hpp"

namespace atrium::assets {
namespace {

// Court layout, metres. Y is up; the long galleries run along X.
constexpr float kHalfLength = 17.0f;       // outer walls at x = +-17
constexpr float kHalfWidth = 14.0f;        // outer walls at z = +-14
constexpr float kColonnadeZ = 10.0f;       // column line of each gallery
constexpr int kColumnsPerSide = 11;        // at x = -15, -12, ..., 15
constexpr float kColumnSpacing = 3.0f;
constexpr float kColumnHeight = 5.2f;      // base to top of capital
constexpr float kArchHeight = 1.8f;        // arch panel above the capitals
constexpr float kSlabThickness = 0.3f;
constexpr float kStorey = kColumnHeight + kArchHeight + kSlabThickness;  // 7.3 m
constexpr float kWallHeight = 2.0f * kStorey;
constexpr int kTextureSize = 256;

enum MaterialSlot : std::uint32_t {
  kFloor, kBrick, kMarble, kSandstone, kWood, kBannerRed, kBannerBlue, kBannerGreen, kLampGlass, kBronze, kMaterialCount
};

struct MaterialSpec {
  const char* name;
  SurfacePattern pattern;
  AlphaMode alpha;
  bool double_sided;
  float emissive_strength;
};

constexpr std::array<MaterialSpec, kMaterialCount> kMaterials{{
    {"floor_stone", SurfacePattern::StoneTiles, AlphaMode::Opaque, false, 0.0f},
    {"wall_brick", SurfacePattern::Bricks, AlphaMode::Opaque, false, 0.0f},
    {"column_marble", SurfacePattern::Marble, AlphaMode::Opaque, false, 0.0f},
    {"arch_sandstone", SurfacePattern::Sandstone, AlphaMode::Opaque, false, 0.0f},
    {"wood_planks", SurfacePattern::WoodPlanks, AlphaMode::Opaque, false, 0.0f},
    {"banner_red", SurfacePattern::BannerRed, AlphaMode::Mask, true, 1.0f},
    {"banner_blue", SurfacePattern::BannerBlue, AlphaMode::Mask, true, 1.0f},
    {"banner_green", SurfacePattern::BannerGreen, AlphaMode::Mask, true, 1.0f},
    {"lamp_glass", SurfacePattern::LampGlass, AlphaMode::Opaque, false, 6.0f},
    {"bronze", SurfacePattern::Bronze, AlphaMode::Opaque, false, 0.0f},
}};

std::vector<Material> make_materials(AssetManager& assets) {
  std::vector<Material> materials;
  for (const MaterialSpec& spec : kMaterials) {
    MaterialImages images = generate_material_images(spec.pattern, kTextureSize);
    const std::string key = std::string("builtin:") + spec.name;
    Material m;
    m.name = spec.name;
    m.metallic_factor = 1.0f;   // the texture carries the actual values
    m.roughness_factor = 1.0f;
    m.alpha_mode = spec.alpha;
    m.double_sided = spec.double_sided;
    m.base_color_texture.texture =
        assets.add_texture({key + "/albedo", std::move(images.albedo), ColorSpace::Srgb, std::nullopt}, key + "/albedo");
    m.normal_texture.texture =
        assets.add_texture({key + "/normal", std::move(images.normal), ColorSpace::Linear, std::nullopt}, key + "/normal");
    m.metallic_roughness_texture.texture =
        assets.add_texture({key + "/metallic_roughness", std::move(images.metallic_roughness), ColorSpace::Linear, std::nullopt},
                           key + "/metallic_roughness");
    if (images.emissive) {
      m.emissive_texture.texture =
          assets.add_texture({key + "/emissive", std::move(*images.emissive), ColorSpace::Srgb, std::nullopt}, key + "/emissive");
      m.emissive_factor = glm::vec3(1.0f);
      m.emissive_strength = spec.emissive_strength;
    }
    materials.push_back(m);
  }
  return materials;
}

Primitive with_material(MeshAsset& asset, Geometry geometry, std::uint32_t material) {
  return add_geometry(asset, std::move(geometry), material);
}

glm::mat4 translate(glm::vec3 t) { return glm::translate(glm::mat4(1.0f), t); }

Mesh floor_mesh(MeshAsset& a) {
  Geometry floor = shapes::grid(glm::vec3(-kHalfLength, 0.0f, kHalfWidth), glm::vec3(2.0f * kHalfLength, 0, 0),
                                 glm::vec3(0, 0, -2.0f * kHalfWidth), 136, 112, 0.25f);
  // Upper gallery floors, paved like the court.
  for (float side : {-1.0f, 1.0f}) {
    const float z0 = side > 0 ? kHalfWidth : -kColonnadeZ + 0.3f;
    Geometry gallery = shapes::grid(glm::vec3(-kHalfLength, kStorey + 0.02f, z0), glm::vec3(2.0f * kHalfLength, 0, 0),
                                     glm::vec3(0, 0, -(kHalfWidth - kColonnadeZ + 0.3f)), 68, 8, 0.25f);
    shapes::append(floor, gallery, glm::mat4(1.0f));
  }
  return {"floor", {with_material(a, std::move(floor), kFloor)}};
}

Mesh walls_mesh(MeshAsset& a) {
  Geometry walls;
  const float h = kWallHeight + kSlabThickness;
  // Inner faces of the four outer walls, facing the court.
  shapes::append(walls, shapes::grid(glm::vec3(-kHalfLength, 0, -kHalfWidth), glm::vec3(2 * kHalfLength, 0, 0), glm::vec3(0, h, 0), 34, 15, 0.5f), glm::mat4(1.0f));
  shapes::append(walls, shapes::grid(glm::vec3(kHalfLength, 0, kHalfWidth), glm::vec3(-2 * kHalfLength, 0, 0), glm::vec3(0, h, 0), 34, 15, 0.5f), glm::mat4(1.0f));
  shapes::append(walls, shapes::grid(glm::vec3(-kHalfLength, 0, kHalfWidth), glm::vec3(0, 0, -2 * kHalfWidth), glm::vec3(0, h, 0), 28, 15, 0.5f), glm::mat4(1.0f));
  shapes::append(walls, shapes::grid(glm::vec3(kHalfLength, 0, -kHalfWidth), glm::vec3(0, 0, 2 * kHalfWidth), glm::vec3(0, h, 0), 28, 15, 0.5f), glm::mat4(1.0f));
  return {"walls", {with_material(a, std::move(walls), kBrick)}};
}

Mesh column_mesh(MeshAsset& a) {
  std::vector<glm::vec2> profile{{0.0f, 0.0f}, {0.48f, 0.0f}, {0.48f, 0.14f}, {0.44f, 0.18f}, {0.42f, 0.24f}, {0.38f, 0.30f}, {0.34f, 0.34f}};
  // The shaft, with a slight entasis (it swells, then narrows towards the top).
  const int shaft_points = 14;
  for (int i = 1; i <= shaft_points; ++i) {
    const float t = static_cast<float>(i) / shaft_points;
    const float y = 0.34f + t * (4.70f - 0.34f);
    const float r = 0.32f + 0.02f * std::sin(t * glm::pi<float>() * 0.8f) - 0.03f * t;
    profile.push_back({r, y});
  }
  for (const glm::vec2 p : {glm::vec2(0.31f, 4.74f), glm::vec2(0.34f, 4.80f), glm::vec2(0.40f, 4.90f), glm::vec2(0.47f, 5.00f),
                            glm::vec2(0.52f, 5.06f), glm::vec2(0.52f, 5.20f), glm::vec2(0.0f, 5.20f)}) {
    profile.push_back(p);
  }
  return {"column", {with_material(a, shapes::lathe(profile, 48, 0.5f), kMarble)}};
}

Mesh arch_mesh(MeshAsset& a) {
  Geometry panel = shapes::arch_panel(kColumnSpacing * 0.5f - 0.42f, kColumnSpacing * 0.5f, kArchHeight, 0.7f, 40, 0.5f);
  return {"arch", {with_material(a, std::move(panel), kSandstone)}};
}

Mesh slab_mesh(MeshAsset& a) {
  Geometry slabs;
  for (int storey = 1; storey <= 2; ++storey) {
    const float y0 = storey * kStorey - kSlabThickness;
    for (float side : {-1.0f, 1.0f}) {
      const float z_in = side * (kColonnadeZ - 0.4f), z_out = side * kHalfWidth;
      shapes::append(slabs, shapes::box(glm::vec3(-kHalfLength, y0, std::min(z_in, z_out)), glm::vec3(kHalfLength, y0 + kSlabThickness, std::max(z_in, z_out)), 0.5f),
                     glm::mat4(1.0f));
    }
  }
  return {"slabs", {with_material(a, std::move(slabs), kSandstone)}};
}

Mesh balustrade_mesh(MeshAsset& a) {
  // Balusters and a wooden rail between the upper columns, on both galleries.
  const std::vector<glm::vec2> baluster{{0.0f, 0.0f}, {0.09f, 0.0f}, {0.09f, 0.08f}, {0.06f, 0.12f}, {0.05f, 0.2f}, {0.08f, 0.32f},
                                        {0.1f, 0.42f}, {0.08f, 0.52f}, {0.05f, 0.62f}, {0.045f, 0.72f}, {0.07f, 0.78f}, {0.07f, 0.86f}, {0.0f, 0.86f}};
  const Geometry one = shapes::lathe(baluster, 16, 2.0f);
  Geometry balusters, rails;
  for (float side : {-1.0f, 1.0f}) {
    const float z = side * kColonnadeZ;
    for (int bay = 0; bay + 1 < kColumnsPerSide; ++bay) {
      const float x0 = -15.0f + kColumnSpacing * static_cast<float>(bay);
      for (int b = 1; b <= 7; ++b) {
        shapes::append(balusters, one, translate(glm::vec3(x0 + kColumnSpacing * static_cast<float>(b) / 8.0f, kStorey, z)));
      }
    }
    shapes::append(rails, shapes::box(glm::vec3(-15.0f, kStorey + 0.86f, z - 0.12f), glm::vec3(15.0f, kStorey + 0.96f, z + 0.12f), 1.0f), glm::mat4(1.0f));
  }
  return {"balustrade", {with_material(a, std::move(balusters), kMarble), with_material(a, std::move(rails), kWood)}};
}

Mesh doors_mesh(MeshAsset& a) {
  Geometry doors;
  for (float side : {-1.0f, 1.0f}) {
    const float x = side * kHalfLength;
    shapes::append(doors, shapes::box(glm::vec3(x - 0.08f, 0.0f, -1.6f), glm::vec3(x + 0.08f, 4.2f, 1.6f), 0.35f), glm::mat4(1.0f));
  }
  return {"doors", {with_material(a, std::move(doors), kWood)}};
}

Mesh banner_mesh(MeshAsset& a, std::uint32_t material) {
  Geometry cloth = shapes::grid(glm::vec3(-0.6f, 0.0f, 0.0f), glm::vec3(1.2f, 0, 0), glm::vec3(0, 3.6f, 0), 8, 32, 1.0f);
  for (Vertex& v : cloth.vertices) {
    v.uv0 = v.uv1;  // one banner shows the whole pattern once
    v.position.z += 0.05f * std::sin(v.position.y * 2.2f + v.position.x * 3.0f);
  }
  generate_normals(cloth);
  generate_tangents(cloth);
  return {kMaterials[material].name, {with_material(a, std::move(cloth), material)}};
}

constexpr float kPostLampHeight = 3.25f;
constexpr float kHangingLampDrop = 1.35f;  // below the arch's crown

Mesh lamp_post_mesh(MeshAsset& a) {
  const std::vector<glm::vec2> post{{0.0f, 0.0f}, {0.22f, 0.0f}, {0.22f, 0.12f}, {0.1f, 0.25f}, {0.06f, 0.4f}, {0.05f, 2.8f},
                                    {0.09f, 2.95f}, {0.16f, 3.02f}, {0.0f, 3.02f}};
  Geometry placed;
  shapes::append(placed, shapes::sphere(0.24f, 24, 16), translate(glm::vec3(0, kPostLampHeight, 0)));
  return {"lamp_post", {with_material(a, shapes::lathe(post, 24, 1.0f), kBronze), with_material(a, std::move(placed), kLampGlass)}};
}

Mesh hanging_lamp_mesh(MeshAsset& a) {
  // Origin at the arch's crown; the rod hangs down to the glass.
  Geometry rod = shapes::lathe({{0.0f, -kHangingLampDrop + 0.18f}, {0.02f, -kHangingLampDrop + 0.18f}, {0.02f, 0.0f}, {0.0f, 0.0f}}, 12, 1.0f);
  Geometry cap = shapes::lathe({{0.0f, -kHangingLampDrop + 0.12f}, {0.15f, -kHangingLampDrop + 0.12f}, {0.05f, -kHangingLampDrop + 0.22f}, {0.0f, -kHangingLampDrop + 0.22f}}, 24, 1.0f);
  shapes::append(rod, cap, glm::mat4(1.0f));
  Geometry glass;
  shapes::append(glass, shapes::sphere(0.18f, 24, 16), translate(glm::vec3(0, -kHangingLampDrop, 0)));
  return {"hanging_lamp", {with_material(a, std::move(rod), kBronze), with_material(a, std::move(glass), kLampGlass)}};
}

Mesh fountain_mesh(MeshAsset& a) {
  const std::vector<glm::vec2> outer{{2.6f, 0.0f}, {2.6f, 0.55f}, {2.45f, 0.7f}, {2.2f, 0.7f}, {2.2f, 0.1f}, {0.45f, 0.1f},
                                     {0.3f, 0.3f}, {0.24f, 1.2f}, {0.35f, 1.35f}, {0.9f, 1.45f}, {1.05f, 1.6f}, {0.95f, 1.68f},
                                     {0.5f, 1.62f}, {0.2f, 1.7f}, {0.14f, 2.3f}, {0.25f, 2.45f}, {0.12f, 2.6f}, {0.0f, 2.65f}};
  return {"fountain", {with_material(a, shapes::lathe(outer, 96, 0.5f), kMarble)}};
}

float column_x(int index) { return -15.0f + kColumnSpacing * static_cast<float>(index); }

std::vector<glm::vec3> lamp_light_positions() {
  std::vector<glm::vec3> positions;
  for (float z : {-5.0f, 5.0f}) {
    for (float x : {-12.0f, -6.0f, 6.0f, 12.0f}) positions.emplace_back(x, kPostLampHeight, z);
  }
  for (float side : {-1.0f, 1.0f}) {
    for (int bay = 0; bay + 1 < kColumnsPerSide; ++bay) {
      const float crown = kColumnHeight + kColumnSpacing * 0.5f - 0.42f;
      positions.emplace_back(column_x(bay) + kColumnSpacing * 0.5f, crown - kHangingLampDrop, side * kColonnadeZ);
    }
  }
  return positions;
}

// Coloured lights filling the court beyond the lamps.
LightGenerator fill_lights() {
  LightGenerator fill;
  fill.seed = 2024;
  fill.box_min = glm::vec3(-16.0f, 0.4f, -13.0f);
  fill.box_max = glm::vec3(16.0f, 12.5f, 13.0f);
  fill.intensity_min = 0.5f;
  fill.intensity_max = 1.2f;
  return fill;
}

}  // namespace

std::vector<SceneLight> builtin_scene_lights(std::uint32_t count) {
  std::vector<SceneLight> lights;
  for (const glm::vec3& p : lamp_light_positions()) {
    if (lights.size() == count) return lights;
    lights.push_back({p, glm::vec3(1.0f, 0.72f, 0.42f), 1.6f, std::nullopt});
  }
  LightGenerator fill = fill_lights();
  fill.count = count - static_cast<std::uint32_t>(lights.size());
  for (const SceneLight& light : generate_lights(fill)) lights.push_back(light);
  return lights;
}

SceneDescription build_builtin_scene(AssetManager& assets, std::optional<std::uint32_t> light_count) {
  MeshAsset courtyard;
  courtyard.name = kBuiltinSceneName;
  courtyard.materials = make_materials(assets);
  enum MeshSlot : std::uint32_t { kFloorMesh, kWalls, kColumn, kArch, kSlabs, kBalustrade, kDoors, kBannerR, kBannerB, kBannerG,
                                  kLampPost, kHangingLamp, kFountain };
  courtyard.meshes = {floor_mesh(courtyard), walls_mesh(courtyard), column_mesh(courtyard), arch_mesh(courtyard), slab_mesh(courtyard), balustrade_mesh(courtyard), doors_mesh(courtyard),
                      banner_mesh(courtyard, kBannerRed), banner_mesh(courtyard, kBannerBlue), banner_mesh(courtyard, kBannerGreen), lamp_post_mesh(courtyard),
                      hanging_lamp_mesh(courtyard), fountain_mesh(courtyard)};
  const MeshAssetHandle handle = assets.add_mesh_asset(std::move(courtyard), "builtin:atrium");

  SceneDescription scene;
  scene.name = kBuiltinSceneName;
  auto place = [&](std::uint32_t mesh, glm::vec3 position, float yaw_degrees = 0.0f) {
    Transform t;
    t.position = position;
    t.rotation = glm::angleAxis(glm::radians(yaw_degrees), glm::vec3(0, 1, 0));
    scene.instances.push_back({handle, mesh, t});
  };
  for (std::uint32_t mesh : {kFloorMesh, kWalls, kSlabs, kBalustrade, kDoors}) place(mesh, glm::vec3(0.0f));
  const float crown = kColumnHeight + kColumnSpacing * 0.5f - 0.42f;
  int banner = 0;
  for (int storey = 0; storey < 2; ++storey) {
    const float base = static_cast<float>(storey) * kStorey;
    for (float side : {-1.0f, 1.0f}) {
      const float z = side * kColonnadeZ;
      for (int c = 0; c < kColumnsPerSide; ++c) place(kColumn, glm::vec3(column_x(c), base, z));
      for (int bay = 0; bay + 1 < kColumnsPerSide; ++bay) {
        const float x = column_x(bay) + kColumnSpacing * 0.5f;
        place(kArch, glm::vec3(x, base + kColumnHeight, z));
        if (storey == 0) place(kHangingLamp, glm::vec3(x, crown, z));
        if (storey == 1 && bay % 2 == 1) {
          const std::uint32_t mesh = kBannerR + static_cast<std::uint32_t>(banner++ % 3);
          place(mesh, glm::vec3(x, base + 1.8f, z - side * 0.45f), side > 0 ? 180.0f : 0.0f);
        }
      }
    }
  }
  for (float z : {-5.0f, 5.0f}) {
    for (float x : {-12.0f, -6.0f, 6.0f, 12.0f}) place(kLampPost, glm::vec3(x, 0.0f, z));
  }
  place(kFountain, glm::vec3(0.0f));

  scene.lights = builtin_scene_lights(light_count.value_or(kBuiltinDefaultLightCount));
  scene.fill_generator = fill_lights();
  scene.views = {
      {"court", glm::vec3(-15.5f, 1.8f, 0.0f), 90.0f, -4.0f},
      {"gallery", glm::vec3(-15.0f, kStorey + 1.7f, -12.0f), 75.0f, -6.0f},
      {"lamps", glm::vec3(9.0f, 1.9f, 1.5f), -135.0f, 10.0f},
      {"overview", glm::vec3(0.0f, 32.0f, 5.0f), 0.0f, -70.0f},
      {"colonnade", glm::vec3(15.5f, 1.7f, 12.0f), -90.0f, 3.0f},
  };
  scene.ambient = glm::vec3(0.03f);
  scene.background = glm::vec3(0.02f, 0.025f, 0.045f);
  scene.exposure = 2.0f;
  scene.bounds.add(glm::vec3(-kHalfLength, 0.0f, -kHalfWidth));
  scene.bounds.add(glm::vec3(kHalfLength, kWallHeight + kSlabThickness, kHalfWidth));
  return scene;
}

}  // namespace atrium::assets
