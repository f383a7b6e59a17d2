// glTF fixtures written by the test itself through tinygltf's writer, one
// feature each, and the imported data checked value by value.
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>

#include <gtest/gtest.h>
#include <meshoptimizer.h>
#include <nlohmann/json.hpp>
#include <stb_image_write.h>
#include <tiny_gltf.h>

#include "assets/gltf_import.hpp"

namespace atrium::assets {
namespace {
namespace fs = std::filesystem;
using tinygltf::Value;

// Builds a model in memory: one buffer, views, accessors, meshes, nodes.
class Fixture {
 public:
  Fixture() {
    model_.asset.version = "2.0";
    model_.buffers.emplace_back();
    model_.scenes.emplace_back();
    model_.defaultScene = 0;
  }

  int view(const void* data, std::size_t bytes, int stride = 0) {
    auto& buffer = model_.buffers[0].data;
    while (buffer.size() % 4) buffer.push_back(0);
    tinygltf::BufferView v;
    v.buffer = 0;
    v.byteOffset = buffer.size();
    v.byteLength = bytes;
    v.byteStride = static_cast<std::size_t>(stride);
    const auto* p = static_cast<const std::uint8_t*>(data);
    buffer.insert(buffer.end(), p, p + bytes);
    model_.bufferViews.push_back(v);
    return static_cast<int>(model_.bufferViews.size() - 1);
  }

  int accessor(int view, std::size_t offset, int component, int type, std::size_t count, bool normalized = false) {
    tinygltf::Accessor a;
    a.bufferView = view;
    a.byteOffset = offset;
    a.componentType = component;
    a.type = type;
    a.count = count;
    a.normalized = normalized;
    model_.accessors.push_back(a);
    return static_cast<int>(model_.accessors.size() - 1);
  }

  template <typename T>
  int data(const std::vector<T>& values, int component, int type, bool normalized = false) {
    const int count = static_cast<int>(values.size()) / tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(type));
    return accessor(view(values.data(), values.size() * sizeof(T)), 0, component, type, static_cast<std::size_t>(count), normalized);
  }

  // A mesh with one primitive, placed by a new root node.
  int mesh(tinygltf::Primitive primitive, std::vector<double> translation = {}) {
    tinygltf::Mesh mesh;
    mesh.primitives.push_back(std::move(primitive));
    model_.meshes.push_back(mesh);
    tinygltf::Node node;
    node.mesh = static_cast<int>(model_.meshes.size() - 1);
    node.translation = std::move(translation);
    model_.nodes.push_back(node);
    model_.scenes[0].nodes.push_back(static_cast<int>(model_.nodes.size() - 1));
    return node.mesh;
  }

  // One triangle with float positions and the given extra attributes.
  tinygltf::Primitive triangle(bool normals = true) {
    tinygltf::Primitive p;
    p.attributes["POSITION"] = data(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3);
    if (normals) p.attributes["NORMAL"] = data(std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1}, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3);
    p.attributes["TEXCOORD_0"] = data(std::vector<float>{0, 0, 1, 0, 0, 1}, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2);
    p.mode = TINYGLTF_MODE_TRIANGLES;
    return p;
  }

  // A 2x2 PNG stored in the buffer; returns the image index.
  int png_image(std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    const std::uint8_t pixels[16] = {r, g, b, 255, r, g, b, 255, r, g, b, 255, r, g, b, 255};
    std::vector<std::uint8_t> png;
    stbi_write_png_to_func(
        [](void* context, void* data, int size) {
          auto* out = static_cast<std::vector<std::uint8_t>*>(context);
          out->insert(out->end(), static_cast<std::uint8_t*>(data), static_cast<std::uint8_t*>(data) + size);
        },
        &png, 2, 2, 4, pixels, 8);
    tinygltf::Image image;
    image.bufferView = view(png.data(), png.size());
    image.mimeType = "image/png";
    model_.images.push_back(image);
    return static_cast<int>(model_.images.size() - 1);
  }

  int texture(int image, int sampler = -1) {
    tinygltf::Texture t;
    t.source = image;
    t.sampler = sampler;
    model_.textures.push_back(t);
    return static_cast<int>(model_.textures.size() - 1);
  }

  tinygltf::Model& model() { return model_; }

  // Writes the model (.glb, or .gltf with embedded buffers), lets `patch` edit
  // the JSON of a .gltf for what tinygltf's writer does not serialise, imports it.
  ModelImport import(const std::string& name, AssetManager& assets, bool binary = true,
                    const std::function<void(nlohmann::json&)>& patch = {}) {
    const fs::path folder = fs::temp_directory_path() / ("atrium_gltf_fixture_" + std::to_string(::getpid()));
    fs::create_directories(folder);
    const fs::path path = folder / (name + (binary ? ".glb" : ".gltf"));
    if (model_.buffers[0].data.empty()) model_.buffers.erase(model_.buffers.begin());
    tinygltf::TinyGLTF writer;
    EXPECT_TRUE(writer.WriteGltfSceneToFile(&model_, path.string(), true, true, !binary, binary)) << name;
    if (patch) {
      nlohmann::json json = nlohmann::json::parse(std::ifstream(path));
      patch(json);
      std::ofstream(path) << json.dump();
    }
    ModelImport result = import_gltf(path, assets);
    fs::remove_all(folder);
    return result;
  }

 private:
  tinygltf::Model model_;
};

const Primitive& only_primitive(const AssetManager& assets, const ModelImport& imported, std::size_t mesh = 0) {
  return assets.mesh_asset(imported.asset).meshes.at(mesh).primitives.at(0);
}

// The vertices the only primitive of `mesh` indexes.
const std::vector<Vertex>& only_vertices(const AssetManager& assets, const ModelImport& imported, std::size_t mesh = 0) {
  return assets.mesh_asset(imported.asset).vertices(only_primitive(assets, imported, mesh));
}

TEST(GltfFixture, InterleavedStridedAttributesAndEveryIndexType) {
  Fixture f;
  // position.xyz, normal.xyz, uv.xy interleaved with a 40-byte stride (8 bytes of padding).
  std::vector<float> interleaved;
  const float vertices[3][8] = {{0, 0, 0, 0, 0, 1, 0.0f, 0.5f}, {2, 0, 0, 0, 0, 1, 1.0f, 0.5f}, {0, 3, 0, 0, 0, 1, 0.25f, 1.0f}};
  for (const auto& v : vertices) {
    interleaved.insert(interleaved.end(), v, v + 8);
    interleaved.insert(interleaved.end(), {-7.0f, -7.0f});
  }
  const int view = f.view(interleaved.data(), interleaved.size() * sizeof(float), 40);
  const int index_types[] = {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                             TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT};
  for (int type : index_types) {
    tinygltf::Primitive p;
    p.attributes["POSITION"] = f.accessor(view, 0, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, 3);
    p.attributes["NORMAL"] = f.accessor(view, 12, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, 3);
    p.attributes["TEXCOORD_0"] = f.accessor(view, 24, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, 3);
    p.indices = type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ? f.data(std::vector<std::uint8_t>{2, 1, 0, 0}, type, TINYGLTF_TYPE_SCALAR)
                : type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? f.data(std::vector<std::uint16_t>{2, 1, 0, 0}, type, TINYGLTF_TYPE_SCALAR)
                                                                 : f.data(std::vector<std::uint32_t>{2, 1, 0}, type, TINYGLTF_TYPE_SCALAR);
    f.model().accessors[static_cast<std::size_t>(p.indices)].count = 3;
    p.mode = TINYGLTF_MODE_TRIANGLES;
    f.mesh(p);
  }
  AssetManager assets;
  const ModelImport imported = f.import("interleaved", assets);
  for (std::size_t m = 0; m < 3; ++m) {
    const Primitive& p = only_primitive(assets, imported, m);
    const std::vector<Vertex>& vertices = only_vertices(assets, imported, m);
    ASSERT_EQ(vertices.size(), 3u);
    EXPECT_EQ(p.indices, (std::vector<std::uint32_t>{2, 1, 0})) << "mesh " << m;
    EXPECT_EQ(vertices[1].position, glm::vec3(2, 0, 0));
    EXPECT_EQ(vertices[2].position, glm::vec3(0, 3, 0));
    EXPECT_EQ(vertices[2].uv0, glm::vec2(0.25f, 1.0f));
    EXPECT_EQ(vertices[0].normal, glm::vec3(0, 0, 1));
  }
}

TEST(GltfFixture, QuantizedNormalizedAttributesAndTwoUvSets) {
  Fixture f;
  f.model().extensionsUsed = {"KHR_mesh_quantization"};
  f.model().extensionsRequired = {"KHR_mesh_quantization"};
  tinygltf::Primitive p;
  // Positions as plain (not normalised) shorts, padded to 4 components' alignment.
  p.attributes["POSITION"] = f.data(std::vector<std::int16_t>{0, 0, 0, 0, 100, 0, 0, 0, 0, -50, 0, 0}, TINYGLTF_COMPONENT_TYPE_SHORT, TINYGLTF_TYPE_VEC3);
  f.model().accessors.back().count = 3;
  f.model().bufferViews.back().byteStride = 8;
  p.attributes["NORMAL"] = f.data(std::vector<std::int8_t>{0, 0, 127, 0, 0, 0, 127, 0, 0, 0, -128, 0}, TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_TYPE_VEC3, true);
  f.model().accessors.back().count = 3;
  f.model().bufferViews.back().byteStride = 4;
  p.attributes["TEXCOORD_0"] = f.data(std::vector<std::uint16_t>{0, 65535, 32768, 0, 65535, 65535}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_VEC2, true);
  p.attributes["TEXCOORD_1"] = f.data(std::vector<std::uint8_t>{255, 0, 0, 255, 51, 102}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_TYPE_VEC2, true);
  p.mode = TINYGLTF_MODE_TRIANGLES;
  f.mesh(p);
  AssetManager assets;
  const ModelImport imported = f.import("quantized", assets);
  const std::vector<Vertex>& q = only_vertices(assets, imported);
  ASSERT_EQ(q.size(), 3u);
  EXPECT_EQ(q[1].position, glm::vec3(100, 0, 0));
  EXPECT_EQ(q[2].position, glm::vec3(0, -50, 0));
  EXPECT_EQ(q[0].normal, glm::vec3(0, 0, 1));
  EXPECT_EQ(q[2].normal, glm::vec3(0, 0, -1)) << "-128 clamps to -1";
  EXPECT_NEAR(q[1].uv0.x, 32768.0f / 65535.0f, 1e-7f);
  EXPECT_EQ(q[0].uv0, glm::vec2(0.0f, 1.0f));
  EXPECT_EQ(q[0].uv1, glm::vec2(1.0f, 0.0f));
  EXPECT_NEAR(q[2].uv1.y, 0.4f, 1e-6f);
}

TEST(GltfFixture, SparseAccessorsSubstituteElements) {
  Fixture f;
  tinygltf::Primitive p = f.triangle();
  const std::vector<std::uint16_t> indices{2};
  const std::vector<float> values{5, 6, 7};
  const int index_view = f.view(indices.data(), 2);
  const int value_view = f.view(values.data(), 12);
  tinygltf::Accessor& sparse_target = f.model().accessors[static_cast<std::size_t>(p.attributes["POSITION"])];
  sparse_target.sparse.isSparse = true;
  sparse_target.sparse.count = 1;
  sparse_target.sparse.indices.bufferView = index_view;
  sparse_target.sparse.indices.byteOffset = 0;
  sparse_target.sparse.indices.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
  sparse_target.sparse.values.bufferView = value_view;
  sparse_target.sparse.values.byteOffset = 0;
  f.mesh(p);
  AssetManager assets;
  const ModelImport imported = f.import("sparse", assets, false);
  const std::vector<Vertex>& q = only_vertices(assets, imported);
  EXPECT_EQ(q[0].position, glm::vec3(0, 0, 0));
  EXPECT_EQ(q[2].position, glm::vec3(5, 6, 7));
}

TEST(GltfFixture, MissingNormalsAreFlatAndMissingTangentsAreGenerated) {
  Fixture f;
  tinygltf::Primitive p;
  // Two triangles folded along the x axis, sharing two vertices.
  p.attributes["POSITION"] = f.data(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3);
  p.attributes["TEXCOORD_0"] = f.data(std::vector<float>{0, 0, 1, 0, 0, 1, 0, 1}, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2);
  p.indices = f.data(std::vector<std::uint16_t>{0, 1, 2, 0, 3, 1}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_SCALAR);
  p.mode = TINYGLTF_MODE_TRIANGLES;
  f.mesh(p);
  AssetManager assets;
  const ModelImport imported = f.import("flat", assets);
  const std::vector<Vertex>& q = only_vertices(assets, imported);
  ASSERT_EQ(q.size(), 6u) << "flat shading gives every corner its own vertex";
  for (int v = 0; v < 3; ++v) EXPECT_NEAR(q[static_cast<std::size_t>(v)].normal.z, 1.0f, 1e-6f);
  for (int v = 3; v < 6; ++v) EXPECT_NEAR(q[static_cast<std::size_t>(v)].normal.y, 1.0f, 1e-6f);
  for (const Vertex& v : q) {
    EXPECT_NEAR(glm::dot(glm::vec3(v.tangent), v.normal), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(glm::vec3(v.tangent)), 1.0f, 1e-6f);
  }
  EXPECT_NEAR(q[0].tangent.x, 1.0f, 1e-6f) << "u grows along +x";
}

TEST(GltfFixture, MaterialsWithEveryTextureFactorAndExtension) {
  Fixture f;
  f.model().extensionsUsed = {"KHR_materials_emissive_strength", "KHR_texture_transform", "EXT_made_up"};
  const int red = f.png_image(255, 0, 0);
  const int grey = f.png_image(128, 128, 128);
  tinygltf::Sampler nearest_clamp;
  nearest_clamp.magFilter = TINYGLTF_TEXTURE_FILTER_NEAREST;
  nearest_clamp.minFilter = TINYGLTF_TEXTURE_FILTER_NEAREST;
  nearest_clamp.wrapS = TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
  nearest_clamp.wrapT = TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT;
  f.model().samplers.push_back(nearest_clamp);
  const int red_texture = f.texture(red, 0);
  const int grey_texture = f.texture(grey);

  tinygltf::Material m;
  m.name = "everything";
  m.pbrMetallicRoughness.baseColorFactor = {0.5, 0.25, 1.0, 0.75};
  m.pbrMetallicRoughness.metallicFactor = 0.3;
  m.pbrMetallicRoughness.roughnessFactor = 0.6;
  m.pbrMetallicRoughness.baseColorTexture.index = red_texture;
  m.pbrMetallicRoughness.metallicRoughnessTexture.index = grey_texture;
  m.normalTexture.index = grey_texture;
  m.normalTexture.scale = 0.4;
  m.occlusionTexture.index = grey_texture;
  m.occlusionTexture.strength = 0.7;
  m.occlusionTexture.texCoord = 1;
  m.emissiveTexture.index = red_texture;
  m.emissiveFactor = {1.0, 0.5, 0.0};
  m.extensions["KHR_materials_emissive_strength"] = Value(Value::Object{{"emissiveStrength", Value(4.0)}});
  m.pbrMetallicRoughness.baseColorTexture.extensions["KHR_texture_transform"] = Value(Value::Object{
      {"offset", Value(Value::Array{Value(0.5), Value(0.25)})},
      {"rotation", Value(1.5707963267948966)},
      {"scale", Value(Value::Array{Value(2.0), Value(3.0)})},
      {"texCoord", Value(1)}});
  m.alphaMode = "MASK";
  m.alphaCutoff = 0.3;
  m.doubleSided = true;
  f.model().materials.push_back(m);
  tinygltf::Material blend;
  blend.name = "glass";
  blend.alphaMode = "BLEND";
  blend.pbrMetallicRoughness.baseColorTexture.index = red_texture;  // the same image as above
  f.model().materials.push_back(blend);

  for (int material = 0; material < 2; ++material) {
    tinygltf::Primitive p = f.triangle();
    p.material = material;
    f.mesh(p);
  }
  AssetManager assets;
  const ModelImport imported = f.import("materials", assets);
  const auto& materials = assets.mesh_asset(imported.asset).materials;
  ASSERT_EQ(materials.size(), 2u);
  const Material& e = materials[0];
  EXPECT_EQ(e.name, "everything");
  EXPECT_EQ(e.base_color_factor, glm::vec4(0.5f, 0.25f, 1.0f, 0.75f));
  EXPECT_FLOAT_EQ(e.metallic_factor, 0.3f);
  EXPECT_FLOAT_EQ(e.roughness_factor, 0.6f);
  EXPECT_FLOAT_EQ(e.normal_scale, 0.4f);
  EXPECT_FLOAT_EQ(e.occlusion_strength, 0.7f);
  EXPECT_EQ(e.occlusion_texture.uv_set, 1);
  EXPECT_EQ(e.emissive_factor, glm::vec3(1.0f, 0.5f, 0.0f));
  EXPECT_FLOAT_EQ(e.emissive_strength, 4.0f);
  EXPECT_EQ(e.alpha_mode, AlphaMode::Mask);
  EXPECT_FLOAT_EQ(e.alpha_cutoff, 0.3f);
  EXPECT_TRUE(e.double_sided);
  EXPECT_EQ(materials[1].alpha_mode, AlphaMode::Blend);
  // Sampler: glTF's codes kept.
  EXPECT_EQ(e.base_color_texture.sampler.mag_filter, SamplerDesc::kNearest);
  EXPECT_EQ(e.base_color_texture.sampler.wrap_s, SamplerDesc::kClampToEdge);
  EXPECT_EQ(e.base_color_texture.sampler.wrap_t, SamplerDesc::kMirroredRepeat);
  EXPECT_EQ(e.metallic_roughness_texture.sampler, SamplerDesc{});
  // KHR_texture_transform: uv' = T * R * S * uv, with texCoord overriding the set.
  const glm::vec3 uv = e.base_color_texture.uv_transform * glm::vec3(1.0f, 0.0f, 1.0f);
  EXPECT_NEAR(uv.x, 0.5f, 1e-6f);  // scale (2, 3) -> (2, 0); the spec's rotation by 90 deg -> (0, 2); offset -> (0.5, 2.25)
  EXPECT_NEAR(uv.y, 2.25f, 1e-6f);
  EXPECT_EQ(e.base_color_texture.uv_set, 1);
  // Colour spaces; the red image serves base colour in both materials and the
  // emissive slot (all sRGB) through one texture.
  EXPECT_EQ(assets.texture(e.base_color_texture.texture).color_space, ColorSpace::Srgb);
  EXPECT_EQ(assets.texture(e.normal_texture.texture).color_space, ColorSpace::Linear);
  EXPECT_EQ(e.base_color_texture.texture, materials[1].base_color_texture.texture);
  EXPECT_EQ(e.base_color_texture.texture, e.emissive_texture.texture);
  EXPECT_EQ(assets.texture_count(), 2u);
  const Image& red_pixels = assets.texture(e.base_color_texture.texture).image;
  EXPECT_EQ(red_pixels.width, 2);
  EXPECT_EQ(red_pixels.rgba[0], 255);
  EXPECT_EQ(red_pixels.rgba[1], 0);
  // One warning for the unknown optional extension.
  int made_up = 0;
  for (const auto& w : imported.warnings) made_up += w.find("EXT_made_up") != std::string::npos;
  EXPECT_EQ(made_up, 1);
}

TEST(GltfFixture, MissingAndCorruptImagesWarnAndFallBackToNeutral) {
  Fixture f;
  tinygltf::Image missing;
  missing.uri = "does-not-exist.png";
  f.model().images.push_back(missing);
  const std::uint8_t garbage[] = {1, 2, 3, 4, 5, 6, 7, 8};
  tinygltf::Image corrupt;
  corrupt.bufferView = f.view(garbage, sizeof garbage);
  corrupt.mimeType = "image/png";
  f.model().images.push_back(corrupt);
  tinygltf::Material m;
  m.pbrMetallicRoughness.baseColorTexture.index = f.texture(0);
  m.normalTexture.index = f.texture(1);
  f.model().materials.push_back(m);
  tinygltf::Primitive p = f.triangle();
  p.material = 0;
  f.mesh(p);
  AssetManager assets;
  const ModelImport imported = f.import("bad-images", assets, false);
  const Material& material = assets.mesh_asset(imported.asset).materials[0];
  EXPECT_FALSE(material.base_color_texture.valid());
  EXPECT_FALSE(material.normal_texture.valid());
  int image_warnings = 0;
  for (const auto& w : imported.warnings) image_warnings += w.find("neutral default texture") != std::string::npos;
  EXPECT_EQ(image_warnings, 2);
}

TEST(GltfFixture, NodeHierarchyCombinesTrsAndMatrices) {
  Fixture f;
  f.mesh(f.triangle());
  auto& model = f.model();
  // Root (TRS: translate x+10, rotate 90 deg about y) -> child (matrix: translate z+2, scale 3) -> mesh.
  tinygltf::Node child = model.nodes[0];
  child.translation.clear();
  child.matrix = {3, 0, 0, 0, 0, 3, 0, 0, 0, 0, 3, 0, 0, 0, 2, 1};
  tinygltf::Node root;
  root.translation = {10, 0, 0};
  root.rotation = {0, std::sin(glm::radians(45.0)), 0, std::cos(glm::radians(45.0))};
  root.children = {1};
  model.nodes = {root, child};
  model.scenes[0].nodes = {0};
  AssetManager assets;
  const ModelImport imported = f.import("hierarchy", assets);
  ASSERT_EQ(imported.instances.size(), 1u);
  const Transform& t = imported.instances[0].transform;
  EXPECT_NEAR(t.position.x, 12.0f, 1e-5f);  // (0, 0, 2) rotated 90 deg about y is (2, 0, 0)
  EXPECT_NEAR(t.position.z, 0.0f, 1e-5f);
  EXPECT_NEAR(t.scale.x, 3.0f, 1e-5f);
  const glm::vec3 x_axis = t.rotation * glm::vec3(1, 0, 0);
  EXPECT_NEAR(x_axis.z, -1.0f, 1e-5f);
}

TEST(GltfFixture, PunctualLightsBecomeSceneLightsInAtriumUnits) {
  Fixture f;
  f.model().extensionsUsed = {"KHR_lights_punctual"};
  tinygltf::Light point, spot, sun;
  point.type = "point";
  point.color = {1.0, 0.5, 0.25};
  point.intensity = 683.0;
  point.range = 12.0;
  spot.type = "spot";
  spot.intensity = 1366.0;
  spot.spot.innerConeAngle = 0.2;
  spot.spot.outerConeAngle = 0.6;
  sun.type = "directional";
  sun.intensity = 6830.0;
  f.model().lights = {point, spot, sun};
  const double s = std::sin(glm::radians(-45.0)), c = std::cos(glm::radians(-45.0));
  for (int i = 0; i < 3; ++i) {
    tinygltf::Node node;
    node.translation = {static_cast<double>(i), 5.0, 0.0};
    node.rotation = {s, 0, 0, c};  // -90 deg about x: -Z turns to -Y
    node.extensions["KHR_lights_punctual"] = Value(Value::Object{{"light", Value(i)}});
    f.model().nodes.push_back(node);
    f.model().scenes[0].nodes.push_back(i);
  }
  AssetManager assets;
  const ModelImport imported = f.import("lights", assets, false);
  ASSERT_EQ(imported.lights.size(), 3u);
  const SceneLight& p = imported.lights[0];
  EXPECT_EQ(p.kind, LightKind::Point);
  EXPECT_FLOAT_EQ(p.intensity, 1.0f);
  EXPECT_EQ(p.color, glm::vec3(1.0f, 0.5f, 0.25f));
  EXPECT_EQ(*p.radius, 12.0f);
  EXPECT_EQ(p.position, glm::vec3(0, 5, 0));
  const SceneLight& sp = imported.lights[1];
  EXPECT_EQ(sp.kind, LightKind::Spot);
  EXPECT_FLOAT_EQ(sp.intensity, 2.0f);
  EXPECT_FLOAT_EQ(sp.inner_cone, 0.2f);
  EXPECT_FLOAT_EQ(sp.outer_cone, 0.6f);
  EXPECT_NEAR(sp.direction.y, -1.0f, 1e-6f);
  EXPECT_FALSE(sp.radius.has_value()) << "no range: derived from intensity later";
  EXPECT_EQ(imported.lights[2].kind, LightKind::Directional);
  EXPECT_FLOAT_EQ(imported.lights[2].intensity, 10.0f);
}

TEST(GltfFixture, NonTrianglePrimitivesAreSkippedWithAWarning) {
  Fixture f;
  tinygltf::Primitive lines = f.triangle();
  lines.mode = TINYGLTF_MODE_LINE;
  f.mesh(lines);
  f.model().meshes[0].primitives.push_back(f.triangle());
  AssetManager assets;
  const ModelImport imported = f.import("lines", assets);
  EXPECT_EQ(assets.mesh_asset(imported.asset).meshes[0].primitives.size(), 1u);
  ASSERT_FALSE(imported.warnings.empty());
  EXPECT_NE(imported.warnings[0].find("not triangles"), std::string::npos) << imported.warnings[0];
}

TEST(GltfFixture, UnsupportedRequiredExtensionIsAnError) {
  Fixture f;
  f.mesh(f.triangle());
  f.model().extensionsUsed = {"KHR_texture_basisu"};
  f.model().extensionsRequired = {"KHR_texture_basisu"};
  AssetManager assets;
  try {
    (void)f.import("basisu", assets);
    FAIL() << "accepted";
  } catch (const ImportError& e) {
    EXPECT_NE(std::string(e.what()).find("requires the extension KHR_texture_basisu, which Atrium does not support"),
              std::string::npos) << e.what();
  }
}

TEST(GltfFixture, MeshoptCompressedBuffersAreDecoded) {
  Fixture f;
  f.model().extensionsUsed = {"EXT_meshopt_compression"};
  f.model().extensionsRequired = {"EXT_meshopt_compression"};
  // Positions of a quad, 12-byte stride, and its indices, both compressed.
  const std::vector<float> positions{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  const std::vector<std::uint32_t> indices{0, 1, 2, 0, 2, 3};
  std::vector<std::uint8_t> vertex_stream(meshopt_encodeVertexBufferBound(4, 12));
  vertex_stream.resize(meshopt_encodeVertexBuffer(vertex_stream.data(), vertex_stream.size(), positions.data(), 4, 12));
  std::vector<std::uint8_t> index_stream(meshopt_encodeIndexBufferBound(6, 4));
  index_stream.resize(meshopt_encodeIndexBuffer(index_stream.data(), index_stream.size(), indices.data(), 6));
  // The compressed bytes live in buffer 0; the views point at a fallback buffer
  // 1. tinygltf's writer drops bufferView extensions, so they are patched in.
  std::map<std::size_t, nlohmann::json> extensions;
  auto compressed = [&](const std::vector<std::uint8_t>& stream, std::size_t stride, std::size_t count, const char* mode) {
    const int raw = f.view(stream.data(), stream.size());
    const tinygltf::BufferView source = f.model().bufferViews[static_cast<std::size_t>(raw)];
    tinygltf::BufferView v;
    v.buffer = 1;
    v.byteLength = stride * count;
    v.byteStride = std::string(mode) == "ATTRIBUTES" ? stride : 0;
    f.model().bufferViews.push_back(v);
    extensions[f.model().bufferViews.size() - 1] = {{"buffer", 0}, {"byteOffset", source.byteOffset}, {"byteLength", source.byteLength},
                                                   {"byteStride", stride}, {"count", count}, {"mode", mode}};
    return static_cast<int>(f.model().bufferViews.size() - 1);
  };
  // INDICES mode (an index sequence, as encoders write for non-triangle or
  // unordered lists), 16-bit: the same quad, its second triangle first.
  const std::vector<std::uint16_t> sequence{0, 2, 3, 0, 1, 2};
  std::vector<std::uint8_t> sequence_stream(meshopt_encodeIndexSequenceBound(6, 4));
  const std::vector<std::uint32_t> sequence32(sequence.begin(), sequence.end());
  sequence_stream.resize(meshopt_encodeIndexSequence(sequence_stream.data(), sequence_stream.size(), sequence32.data(), 6));
  const int position_view = compressed(vertex_stream, 12, 4, "ATTRIBUTES");
  const int index_view = compressed(index_stream, 4, 6, "TRIANGLES");
  const int sequence_view = compressed(sequence_stream, 2, 6, "INDICES");
  tinygltf::Buffer fallback;
  fallback.data.resize(12 * 4 + 4 * 6 + 2 * 6);
  f.model().buffers.push_back(fallback);
  tinygltf::Primitive p;
  p.attributes["POSITION"] = f.accessor(position_view, 0, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, 4);
  p.indices = f.accessor(index_view, 0, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, 6);
  p.mode = TINYGLTF_MODE_TRIANGLES;
  f.mesh(p);
  tinygltf::Primitive sequenced = p;
  sequenced.indices = f.accessor(sequence_view, 0, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_SCALAR, 6);
  f.mesh(sequenced);
  AssetManager assets;
  const ModelImport imported = f.import("meshopt", assets, false, [&](nlohmann::json& json) {
    for (const auto& [view, extension] : extensions) json["bufferViews"][view]["extensions"]["EXT_meshopt_compression"] = extension;
  });
  const std::vector<Vertex>& q = only_vertices(assets, imported);
  // No normals: flat shading unwelds to six corners, in index order.
  ASSERT_EQ(q.size(), 6u);
  const glm::vec3 expected[] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(q[i].position, expected[i]) << i;
  const std::vector<Vertex>& from_sequence = only_vertices(assets, imported, 1);
  ASSERT_EQ(from_sequence.size(), 6u);
  const glm::vec3 expected_sequence[] = {{0, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
  for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(from_sequence[i].position, expected_sequence[i]) << "INDICES " << i;
}

TEST(GltfFixture, SponzaStandInManyMaterialsShareFewImages) {
  // Sponza's traits: 25 materials over a handful of images, alpha-masked
  // foliage and chains, and both 16- and 32-bit index buffers.
  Fixture f;
  std::vector<int> textures;
  for (int i = 0; i < 6; ++i) textures.push_back(f.texture(f.png_image(static_cast<std::uint8_t>(40 * i), 100, 200)));
  for (int i = 0; i < 25; ++i) {
    tinygltf::Material m;
    m.name = "material_" + std::to_string(i);
    m.pbrMetallicRoughness.baseColorTexture.index = textures[static_cast<std::size_t>(i % 6)];
    if (i % 5 == 0) {
      m.alphaMode = "MASK";
      m.alphaCutoff = 0.5;
      m.doubleSided = true;
    }
    f.model().materials.push_back(m);
    tinygltf::Primitive p = f.triangle();
    p.material = i;
    p.indices = i % 2 ? f.data(std::vector<std::uint16_t>{0, 1, 2}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_SCALAR)
                      : f.data(std::vector<std::uint32_t>{0, 1, 2}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR);
    f.mesh(p);
  }
  AssetManager assets;
  const ModelImport imported = f.import("sponza-stand-in", assets);
  const MeshAsset& asset = assets.mesh_asset(imported.asset);
  EXPECT_EQ(asset.materials.size(), 25u);
  EXPECT_EQ(assets.texture_count(), 6u) << "each image is decoded and kept once";
  EXPECT_EQ(imported.images, 6u);
  std::size_t masked = 0;
  for (const Material& m : asset.materials) masked += m.alpha_mode == AlphaMode::Mask;
  EXPECT_EQ(masked, 5u);
  EXPECT_EQ(imported.instances.size(), 25u);
  for (const Mesh& mesh : asset.meshes) EXPECT_EQ(mesh.primitives.at(0).indices, (std::vector<std::uint32_t>{0, 1, 2}));
}

}  // namespace
}  // namespace atrium::assets
