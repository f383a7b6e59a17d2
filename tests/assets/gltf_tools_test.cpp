// Files written by other tools (tests/data/gltf-tools, made by make_fixtures.sh
// with gltfpack, glTF-Transform and Blender from ../shared/testdata): each
// imports with its source's triangles, values decode close to the source's,
// and what each tool wrote (filters, instancing, colours, unlit) is read.
// Renders are compared with their sources in tests/render/gltf_render_test.cpp.
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>

#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "assets/gltf_import.hpp"
#include "assets/meshlets.hpp"
#include "support/model_triangles.hpp"

namespace atrium::assets {
namespace {
namespace fs = std::filesystem;

const fs::path kFixtures = fs::path(ATRIUM_SOURCE_DIR) / "tests/data/gltf-tools";
const fs::path kTestdata = fs::path(ATRIUM_TESTDATA_DIR);

using testing::drawn_triangles;

// The JSON of a .glb, to check what the tool actually wrote.
nlohmann::json glb_json(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::uint32_t header[5];
  in.read(reinterpret_cast<char*>(header), sizeof header);
  std::string text(header[3], '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  return nlohmann::json::parse(text);
}

struct ToolFixture {
  std::string file;  // in tests/data/gltf-tools
  fs::path source;   // what the tool read
};

std::vector<ToolFixture> tool_fixtures() {
  const fs::path blender = kTestdata / "gltf/blender-exports";
  const fs::path colors = kFixtures / "blender-colors.glb";
  std::vector<ToolFixture> fixtures;
  for (const char* model : {"teapot", "torusknot", "subpass_scene_opaque"}) {
    for (const char* flags : {"c", "cc", "c-noq", "cc-noq"}) {
      fixtures.push_back({std::string(model) + ".gltfpack-" + flags + ".glb", blender / (std::string(model) + ".gltf")});
    }
  }
  fixtures.push_back({"blender-colors.gltfpack-cc-mi.glb", colors});
  fixtures.push_back({"blender-colors.gltfpack-c.glb", colors});
  fixtures.push_back({"blender-colors.gltfpack-cc.glb", colors});
  fixtures.push_back({"teapot.draco-edgebreaker.glb", blender / "teapot.gltf"});
  fixtures.push_back({"teapot.draco-sequential.glb", blender / "teapot.gltf"});
  fixtures.push_back({"torusknot.draco-edgebreaker.glb", blender / "torusknot.gltf"});
  fixtures.push_back({"torusknot.quantized.draco-edgebreaker.glb", blender / "torusknot.gltf"});
  fixtures.push_back({"blender-colors.draco-edgebreaker.glb", colors});
  return fixtures;
}

class ToolWritten : public ::testing::TestWithParam<ToolFixture> {};

TEST_P(ToolWritten, ImportsWithItsSourcesTrianglesAndNoWarningBeyondTheSources) {
  AssetManager assets;
  const ModelImport source = import_gltf(GetParam().source, assets);
  const ModelImport fixture = import_gltf(kFixtures / GetParam().file, assets);
  EXPECT_EQ(drawn_triangles(assets, fixture), drawn_triangles(assets, source));
  EXPECT_GT(drawn_triangles(assets, fixture), 0u);
  // Tools keep their sources' flaws (zero-area triangles, zero-length
  // normals); a fixture may be warned of those, and of nothing else.
  auto kind = [](const std::string& warning) {
    for (const char* k : {"zero area", "invalid normals"}) {
      if (warning.find(k) != std::string::npos) return std::string(k);
    }
    return warning;
  };
  std::set<std::string> source_kinds;
  for (const std::string& warning : source.warnings) source_kinds.insert(kind(warning));
  for (const std::string& warning : fixture.warnings) EXPECT_TRUE(source_kinds.contains(kind(warning))) << warning;
  // The box the triangles fill survives compression (quantisation moves it by a step).
  const float size = glm::length(source.bounds.max - source.bounds.min);
  EXPECT_LT(glm::length(fixture.bounds.min - source.bounds.min), size * 2e-3f);
  EXPECT_LT(glm::length(fixture.bounds.max - source.bounds.max), size * 2e-3f);
}

INSTANTIATE_TEST_SUITE_P(GltfTools, ToolWritten, ::testing::ValuesIn(tool_fixtures()), [](const auto& info) {
  std::string name = info.param.file.substr(0, info.param.file.size() - 4);
  for (char& c : name) if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
});

TEST(GltfTools, TheFixturesCoverEveryMeshoptModeFilterAndDracoAttribute) {
  std::set<std::string> filters, modes, draco_attributes;
  for (const auto& entry : fs::directory_iterator(kFixtures)) {
    if (entry.path().extension() != ".glb") continue;
    const nlohmann::json j = glb_json(entry.path());
    for (const auto& view : j.value("bufferViews", nlohmann::json::array())) {
      if (!view.contains("extensions") || !view["extensions"].contains("EXT_meshopt_compression")) continue;
      const auto& ext = view["extensions"]["EXT_meshopt_compression"];
      modes.insert(ext["mode"].get<std::string>());
      filters.insert(ext.value("filter", "NONE"));
    }
    for (const auto& mesh : j.value("meshes", nlohmann::json::array())) {
      for (const auto& primitive : mesh["primitives"]) {
        if (!primitive.contains("extensions") || !primitive["extensions"].contains("KHR_draco_mesh_compression")) continue;
        for (const auto& [semantic, id] : primitive["extensions"]["KHR_draco_mesh_compression"]["attributes"].items()) {
          draco_attributes.insert(semantic);
        }
      }
    }
  }
  EXPECT_EQ(filters, (std::set<std::string>{"NONE", "OCTAHEDRAL", "QUATERNION", "EXPONENTIAL"}));
  EXPECT_TRUE(modes.contains("ATTRIBUTES") && modes.contains("TRIANGLES"));  // INDICES: gltf_fixture_test
  EXPECT_EQ(draco_attributes, (std::set<std::string>{"POSITION", "NORMAL", "TEXCOORD_0", "TANGENT", "COLOR_0"}));
}

TEST(GltfTools, GpuInstancingBecomesOneInstancePerTransform) {
  AssetManager assets;
  const ModelImport imported = import_gltf(kFixtures / "blender-colors.gltfpack-cc-mi.glb", assets);
  const nlohmann::json j = glb_json(kFixtures / "blender-colors.gltfpack-cc-mi.glb");
  std::size_t declared = 0, plain = 0;
  for (const auto& node : j["nodes"]) {
    if (!node.contains("mesh")) continue;
    if (node.contains("extensions") && node["extensions"].contains("EXT_mesh_gpu_instancing")) {
      const int accessor = node["extensions"]["EXT_mesh_gpu_instancing"]["attributes"]["TRANSLATION"];
      declared += j["accessors"][static_cast<std::size_t>(accessor)]["count"].get<std::size_t>();
    } else {
      ++plain;
    }
  }
  EXPECT_GT(declared, 0u);
  EXPECT_EQ(imported.instances.size(), declared + plain);
}

TEST(GltfTools, DracoDecodesPositionsWithinItsQuantisationStep) {
  AssetManager assets;
  const ModelImport source = import_gltf(kTestdata / "gltf/blender-exports/teapot.gltf", assets);
  const ModelImport draco = import_gltf(kFixtures / "teapot.draco-sequential.glb", assets);
  const MeshAsset& a = assets.mesh_asset(source.asset);
  const MeshAsset& b = assets.mesh_asset(draco.asset);
  // 16-bit positions over the teapot's 6.4 m: steps of 0.1 mm. Every decoded
  // corner lies on a source corner, within a step.
  const auto& sv = a.vertex_buffers.at(0);
  const auto& dv = b.vertex_buffers.at(0);
  float worst = 0.0f;
  for (std::size_t i = 0; i < dv.size(); i += 37) {
    float nearest = 1e9f;
    for (const Vertex& v : sv) nearest = std::min(nearest, glm::distance(v.position, dv[i].position));
    worst = std::max(worst, nearest);
  }
  EXPECT_LT(worst, 2e-4f);
}

// A .glb with its JSON replaced (its BIN chunk kept byte for byte).
void write_glb_with_json(const fs::path& from, const nlohmann::json& j, const fs::path& to) {
  std::ifstream in(from, std::ios::binary);
  std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::uint32_t json_length = 0;
  std::memcpy(&json_length, bytes.data() + 12, 4);
  const std::vector<char> binary(bytes.begin() + 20 + json_length, bytes.end());
  std::string text = j.dump();
  text.resize((text.size() + 3) / 4 * 4, ' ');
  const std::uint32_t header[5] = {0x46546C67, 2, static_cast<std::uint32_t>(20 + text.size() + binary.size()),
                                   static_cast<std::uint32_t>(text.size()), 0x4E4F534A};
  std::ofstream out(to, std::ios::binary);
  out.write(reinterpret_cast<const char*>(header), sizeof header);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.write(binary.data(), static_cast<std::streamsize>(binary.size()));
}

TEST(GltfTools, DracoPrimitivesDrawTheirDecodedCountsWhateverTheAccessorsDeclare) {
  // Files in public sample sets declare other counts than their Draco streams
  // decode to (glTF-Sample-Models' BrainStem: 802 declared, 806 decoded; older
  // gltf-pipeline releases wrote the source's counts). glTF-Transform's teapot
  // stream with its accessors' counts set as such files have them: the decoded
  // data draws, with one warning per primitive and kind of count.
  const fs::path fixture = kFixtures / "teapot.draco-edgebreaker.glb";
  AssetManager assets;
  const ModelImport reference = import_gltf(fixture, assets);
  const std::size_t vertices = assets.mesh_asset(reference.asset).vertex_count();
  const fs::path folder = fs::temp_directory_path() / ("atrium_draco_counts_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  for (const long change : {-4L, +7L}) {
    nlohmann::json j = glb_json(fixture);
    const nlohmann::json& primitive = j["meshes"][0]["primitives"][0];
    for (const auto& [semantic, accessor] : primitive["attributes"].items()) {
      j["accessors"][accessor.get<std::size_t>()]["count"] = static_cast<long>(vertices) + change;
    }
    j["accessors"][primitive["indices"].get<std::size_t>()]["count"] = j["accessors"][primitive["indices"].get<std::size_t>()]["count"].get<long>() - 3;
    const fs::path file = folder / ("teapot" + std::to_string(change) + ".glb");
    write_glb_with_json(fixture, j, file);
    const ModelImport imported = import_gltf(file, assets);
    EXPECT_EQ(drawn_triangles(assets, imported), drawn_triangles(assets, reference)) << change;
    EXPECT_EQ(assets.mesh_asset(imported.asset).vertex_count(), vertices) << change;
    std::string all;
    for (const std::string& w : imported.warnings) all += w + "\n";
    const std::string where = file.string() + ": /meshes/0/primitives/0/extensions/KHR_draco_mesh_compression decodes to ";
    EXPECT_NE(all.find(where + std::to_string(vertices) + " vertices, its accessor declares " + std::to_string(static_cast<long>(vertices) + change) +
                       "; the decoded data is used"),
              std::string::npos)
        << all;
    EXPECT_NE(all.find(where + std::to_string(drawn_triangles(assets, reference) * 3) + " indices"), std::string::npos) << all;
    EXPECT_EQ(imported.warnings.size(), reference.warnings.size() + 2) << all;
  }
  fs::remove_all(folder);
}

TEST(GltfTools, JsonThatIsNotGltfIsRefusedNamingWhatIsMissing) {
  // npm's package.json saved as .gltf: valid JSON, no /asset/version.
  AssetManager assets;
  const fs::path file = kFixtures / "not-gltf.npm-package.gltf";
  try {
    (void)import_gltf(file, assets);
    ADD_FAILURE() << "loaded";
  } catch (const ImportError& e) {
    EXPECT_EQ(std::string(e.what()), file.string() + ": is not a glTF file: its JSON has no /asset/version (every glTF names its version there)");
  }
}

TEST(GltfTools, BlenderColoursTangentsAndUnlitAreRead) {
  AssetManager assets;
  const ModelImport imported = import_gltf(kFixtures / "blender-colors.glb", assets);
  const MeshAsset& asset = assets.mesh_asset(imported.asset);
  std::size_t unlit = 0;
  for (const Material& m : asset.materials) unlit += m.unlit;
  EXPECT_EQ(unlit, 1u) << "Blender writes KHR_materials_unlit for a Background shader";
  std::set<std::uint16_t> reds;
  for (const Vertex& v : asset.vertex_buffers.at(0)) {
    reds.insert(v.color[0]);
    ASSERT_NEAR(glm::length(glm::vec3(v.tangent)), 1.0f, 1e-3f);
  }
  EXPECT_GT(reds.size(), 100u) << "COLOR_0 varies over the teapot";
  EXPECT_GE(*reds.begin(), static_cast<std::uint16_t>(0.19f * 65535)) << "Blender's colours start at 0.2";
}

TEST(GltfTools, PrimitivesSharingOneVertexAccessorUploadItOnce) {
  // The shared Sponza's 25 primitives index one accessor of 153,635 vertices.
  AssetManager assets;
  const ModelImport imported = import_gltf(kTestdata / "scenes/sponza-crytek/Sponza.gltf", assets);
  const MeshAsset& asset = assets.mesh_asset(imported.asset);
  EXPECT_EQ(asset.vertex_count(), 153635u);
  EXPECT_EQ(asset.vertex_buffers.size(), 1u);
  std::size_t primitives = 0;
  double sharing = 0.0;
  for (const Mesh& mesh : asset.meshes) {
    primitives += mesh.primitives.size();
    for (const Primitive& p : mesh.primitives) {
      sharing = std::max(sharing, vertex_sharing(p.indices, asset.vertices(p).size()));
      // Every large opaque or masked primitive is cut (meshlets.hpp's sharing
      // limit is for hostile files, not real ones).
      if (p.indices.size() / 3 >= kMeshletMinTriangles && asset.materials.at(p.material).alpha_mode != AlphaMode::Blend) {
        EXPECT_FALSE(p.meshlets.empty()) << "a primitive of " << p.indices.size() / 3 << " triangles";
      }
    }
  }
  EXPECT_EQ(primitives, 25u);
  std::printf("Sponza's most shared primitive: %.1f (limit %.0f)\n", sharing, kMeshletMaxSharing);
}

}  // namespace
}  // namespace atrium::assets
