// The checked glTF reader (gltf_document.hpp): hostile and broken files are
// refused in one line that names the file, the object and the numbers, before
// anything of the declared size is allocated; files that other tools write
// legally (fallback buffers without data, strips, fans) load. Files are written
// as JSON here, byte by byte what a hostile or careless writer could produce.
#include <cstring>
#include <filesystem>
#include <fstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/build_kind.hpp"
#include "assets/gltf_import.hpp"

namespace atrium::assets {
namespace {
namespace fs = std::filesystem;
using json = nlohmann::json;
using ::testing::HasSubstr;
using ::testing::Not;

std::string base64(const std::vector<std::uint8_t>& bytes) {
  static const char* kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::uint32_t n = (bytes[i] << 16) | (i + 1 < bytes.size() ? bytes[i + 1] << 8 : 0) | (i + 2 < bytes.size() ? bytes[i + 2] : 0);
    out += kAlphabet[(n >> 18) & 63];
    out += kAlphabet[(n >> 12) & 63];
    out += i + 1 < bytes.size() ? kAlphabet[(n >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kAlphabet[n & 63] : '=';
  }
  return out;
}

template <typename T>
std::vector<std::uint8_t> bytes_of(const std::vector<T>& values) {
  std::vector<std::uint8_t> out(values.size() * sizeof(T));
  std::memcpy(out.data(), values.data(), out.size());
  return out;
}

// One triangle: 3 float positions then 3 uint16 indices, in one data-URI buffer.
json triangle_gltf() {
  std::vector<std::uint8_t> data = bytes_of(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0});
  const std::vector<std::uint8_t> indices = bytes_of(std::vector<std::uint16_t>{0, 1, 2});
  data.insert(data.end(), indices.begin(), indices.end());
  return {{"asset", {{"version", "2.0"}}},
          {"buffers", {{{"byteLength", data.size()}, {"uri", "data:application/octet-stream;base64," + base64(data)}}}},
          {"bufferViews", {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 36}}, {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 6}}}},
          {"accessors", {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}},
                         {{"bufferView", 1}, {"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}}}},
          {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}}}}}}},
          {"nodes", {{{"mesh", 0}}}},
          {"scenes", {{{"nodes", {0}}}}},
          {"scene", 0}};
}

class GltfDocument : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() / ("atrium_gltf_document_" + std::to_string(::getpid()));
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }

  fs::path write(const std::string& name, const json& document) {
    const fs::path path = folder_ / name;
    std::ofstream(path) << document.dump();
    return path;
  }

  fs::path write_bytes(const std::string& name, const std::vector<std::uint8_t>& bytes) {
    const fs::path path = folder_ / name;
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    return path;
  }

  // The one-line message a file is refused with ("" when it loads).
  std::string refusal(const fs::path& path, std::size_t memory_limit = 0) {
    AssetManager assets;
    try {
      ImportOptions options;
      options.memory_limit = memory_limit;
      (void)import_gltf(path, assets, options);
      return "";
    } catch (const ImportError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.find('\n'), std::string::npos) << "one line: " << what;
      EXPECT_THAT(what, HasSubstr(path.filename().string()));
      for (const char* leak : {"std::", "bad_alloc", "_M_", "basic_string", "json.exception", "vector"}) {
        EXPECT_THAT(what, Not(HasSubstr(leak))) << "no C++ exception text reaches a user";
      }
      return what;
    }
  }

  fs::path folder_;
};

TEST_F(GltfDocument, TheBaseFileLoads) {
  AssetManager assets;
  const ModelImport imported = import_gltf(write("triangle.gltf", triangle_gltf()), assets);
  EXPECT_EQ(imported.instances.size(), 1u);
  EXPECT_FALSE(imported.bounds.empty);
}

TEST_F(GltfDocument, AnAccessorClaimingMoreThanItsViewHoldsIsRefusedBeforeAllocating) {
  json doc = triangle_gltf();
  doc["accessors"][0]["count"] = 4000000000.0;
  EXPECT_THAT(refusal(write("huge-count.gltf", doc)),
              HasSubstr("/accessors/0: reads 4,000,000,000 elements of 12 bytes from byte 0 of /bufferViews/0, which holds 36 bytes"));
}

TEST_F(GltfDocument, OffsetsStridesAndViewsAreCheckedAgainstWhatTheyReferTo) {
  json doc = triangle_gltf();
  doc["bufferViews"][1]["byteLength"] = 600;
  EXPECT_THAT(refusal(write("view.gltf", doc)), HasSubstr("/bufferViews/1: covers bytes 36 to 636 of /buffers/0, which has 42"));
  doc = triangle_gltf();
  doc["accessors"][0]["byteOffset"] = 30;
  EXPECT_THAT(refusal(write("offset.gltf", doc)), HasSubstr("/accessors/0: reads 3 elements of 12 bytes from byte 30"));
  doc = triangle_gltf();
  doc["bufferViews"][0]["byteStride"] = 6;
  EXPECT_THAT(refusal(write("stride.gltf", doc)), HasSubstr("/bufferViews/0/byteStride: expected a multiple of 4, got 6"));
  doc = triangle_gltf();
  doc["meshes"][0]["primitives"][0]["indices"] = 7;
  EXPECT_THAT(refusal(write("index.gltf", doc)),
              HasSubstr("/meshes/0/primitives/0/indices: refers to /accessors/7, which does not exist (the file has 2)"));
  doc = triangle_gltf();
  doc["accessors"][1]["componentType"] = 5000;
  EXPECT_THAT(refusal(write("component.gltf", doc)), HasSubstr("/accessors/1/componentType: expected a glTF component type (5120 to 5126), got 5000"));
}

TEST_F(GltfDocument, BuffersMustHoldTheirDeclaredLength) {
  json doc = triangle_gltf();
  doc["buffers"][0]["byteLength"] = 5000000000.0;
  // Past what a 32-bit size_t can hold, less two bits (sums of offsets and
  // lengths must not wrap): the browser build refuses the number itself.
  EXPECT_THAT(refusal(write("buffer.gltf", doc)),
              HasSubstr(atrium::testing::k32BitSizes ? "/buffers/0/byteLength: expected a whole number from 0 to 1,073,741,823, got 5000000000"
                                                     : "/buffers/0: declares byteLength 5,000,000,000, but its data URI holds 42 bytes"));
  doc = triangle_gltf();
  doc["buffers"][0] = {{"byteLength", 42}, {"uri", "missing.bin"}};
  EXPECT_THAT(refusal(write("missing.gltf", doc)), HasSubstr("/buffers/0: refers to"));
  write_bytes("short.bin", std::vector<std::uint8_t>(10));
  doc["buffers"][0]["uri"] = "short.bin";
  EXPECT_THAT(refusal(write("short.gltf", doc)), HasSubstr("/buffers/0: declares byteLength 42, but short.bin has 10 bytes"));
  doc["buffers"][0] = {{"byteLength", 42}};
  EXPECT_THAT(refusal(write("nodata.gltf", doc)), HasSubstr("/buffers/0: has no uri and is not the BIN chunk of a binary glTF"));
}

TEST_F(GltfDocument, AllocationsBeyondTheMemoryBudgetNameTheFileAndTheSize) {
  // An accessor without a bufferView is all zeros: nothing in the file bounds its count.
  json doc = triangle_gltf();
  doc["accessors"].push_back({{"componentType", 5126}, {"count", 100000}, {"type", "VEC3"}});
  doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 2;
  doc["meshes"][0]["primitives"][0].erase("indices");
  EXPECT_THAT(refusal(write("zeros.gltf", doc), 1 << 20), HasSubstr("/accessors/2 needs 1.1 MiB, more than the 1.0 MiB of memory available"));
  EXPECT_EQ(refusal(write("zeros.gltf", doc), 64 << 20), "") << "within the budget it loads";
}

TEST_F(GltfDocument, TruncatedAndMalformedBinaryGltfIsRefused) {
  const std::string json_text = triangle_gltf().dump();
  std::vector<std::uint8_t> glb(12 + 8);
  const std::uint32_t header[3] = {0x46546C67, 2, static_cast<std::uint32_t>(20 + json_text.size() + 100)};
  std::memcpy(glb.data(), header, 12);
  const std::uint32_t chunk[2] = {static_cast<std::uint32_t>(json_text.size()), 0x4E4F534A};
  std::memcpy(glb.data() + 12, chunk, 8);
  glb.insert(glb.end(), json_text.begin(), json_text.end());
  EXPECT_THAT(refusal(write_bytes("truncated.glb", glb)), HasSubstr("declares a length of"));
  std::uint32_t version = 1;
  std::memcpy(glb.data() + 4, &version, 4);
  EXPECT_THAT(refusal(write_bytes("version.glb", glb)), HasSubstr("binary glTF version 1; Atrium reads version 2"));
  EXPECT_THAT(refusal(write_bytes("header.glb", {0x67, 0x6C, 0x54, 0x46, 2, 0})), HasSubstr("truncated binary glTF"));
}

TEST_F(GltfDocument, NotJsonAndNotGltfAreRefused) {
  const fs::path text = folder_ / "text.gltf";
  std::ofstream(text) << "{\"asset\": ";
  EXPECT_THAT(refusal(text), HasSubstr("not valid JSON"));
  json doc = triangle_gltf();
  doc["asset"]["version"] = "1.0";
  EXPECT_THAT(refusal(write("v1.gltf", doc)), HasSubstr("is glTF version 1.0; Atrium reads glTF 2.0"));
  doc = triangle_gltf();
  doc["accessors"][0]["type"] = "VEC7";
  EXPECT_THAT(refusal(write("type.gltf", doc)), HasSubstr("/accessors/0/type: expected a glTF accessor type (SCALAR, VEC2 ... MAT4), got \"VEC7\""));
}

TEST_F(GltfDocument, AViewIntoADatalessFallbackBufferMustBeCompressed) {
  json doc = triangle_gltf();
  doc["buffers"].push_back({{"byteLength", 36}, {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}});
  doc["bufferViews"].push_back({{"buffer", 1}, {"byteLength", 36}});
  EXPECT_THAT(refusal(write("fallback.gltf", doc)),
              HasSubstr("/bufferViews/2: points into /buffers/1, which holds no data (an EXT_meshopt_compression fallback), and is not compressed"));
}

TEST_F(GltfDocument, MeshoptViewsThatCouldNotHoldTheirDecodedSizeAreRefused) {
  json doc = triangle_gltf();
  doc["extensionsUsed"] = {"EXT_meshopt_compression"};
  doc["buffers"].push_back({{"byteLength", 1200000}, {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}});
  doc["bufferViews"].push_back({{"buffer", 1}, {"byteLength", 1200000}, {"byteStride", 12},
                                {"extensions", {{"EXT_meshopt_compression", {{"buffer", 0}, {"byteLength", 36}, {"byteStride", 12},
                                                                              {"count", 100000}, {"mode", "ATTRIBUTES"}}}}}});
  if (atrium::testing::kBrowserBuild) {
    EXPECT_THAT(refusal(write("expansion.gltf", doc)),
                HasSubstr("/bufferViews/2: EXT_meshopt_compression needs libmeshoptimizer, which the browser build does not have"));
    return;
  }
  EXPECT_THAT(refusal(write("expansion.gltf", doc)), HasSubstr("/bufferViews/2/extensions/EXT_meshopt_compression decodes to 1.1 MiB from 36 bytes"));
  doc["bufferViews"][2]["extensions"]["EXT_meshopt_compression"]["count"] = 3;
  doc["bufferViews"][2]["byteLength"] = 36;
  EXPECT_THAT(refusal(write("corrupt.gltf", doc)), HasSubstr("/bufferViews/2/extensions/EXT_meshopt_compression cannot be decoded (corrupt data"));
  doc["bufferViews"][2]["extensions"]["EXT_meshopt_compression"]["filter"] = "QUATERNION";
  EXPECT_THAT(refusal(write("filter.gltf", doc)), HasSubstr("EXT_meshopt_compression/byteStride: expected 8 for QUATERNION, got 12"));
  doc["bufferViews"][2]["extensions"]["EXT_meshopt_compression"]["mode"] = "TRIANGLES";
  EXPECT_THAT(refusal(write("mode.gltf", doc)), HasSubstr("EXT_meshopt_compression/byteStride: expected 2 or 4 for index modes, got 12"));
}

TEST_F(GltfDocument, CorruptDracoStreamsAreRefusedNamingDraco) {
  json doc = triangle_gltf();
  doc["extensionsUsed"] = doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  doc["accessors"][0].erase("bufferView");
  doc["accessors"][1].erase("bufferView");
  doc["meshes"][0]["primitives"][0]["extensions"] = {
      {"KHR_draco_mesh_compression", {{"bufferView", 0}, {"attributes", {{"POSITION", 0}}}}}};
  EXPECT_THAT(refusal(write("draco.gltf", doc)),
              HasSubstr(atrium::testing::kBrowserBuild
                            ? "/meshes/0/primitives/0: KHR_draco_mesh_compression needs libdraco, which the browser build does not have"
                            : "/meshes/0/primitives/0/extensions/KHR_draco_mesh_compression cannot be decoded"));
}

TEST_F(GltfDocument, StripsAndFansBecomeTriangleLists) {
  json doc = triangle_gltf();
  std::vector<std::uint8_t> data = bytes_of(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0});
  doc["buffers"][0] = {{"byteLength", data.size()}, {"uri", "data:application/octet-stream;base64," + base64(data)}};
  doc["bufferViews"] = {{{"buffer", 0}, {"byteLength", 48}}};
  doc["accessors"] = {{{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}}};
  doc["meshes"][0]["primitives"] = {{{"attributes", {{"POSITION", 0}}}, {"mode", 5}}, {{"attributes", {{"POSITION", 0}}}, {"mode", 6}}};
  AssetManager assets;
  const ModelImport imported = import_gltf(write("strips.gltf", doc), assets);
  const MeshAsset& asset = assets.mesh_asset(imported.asset);
  ASSERT_EQ(asset.meshes[0].primitives.size(), 2u);
  // The strip 0 1 2 3 is the triangles 0 1 2 and 2 1 3 (the second flipped to keep
  // the winding); the fan 0 1 2 3 is 0 1 2 and 0 2 3. Without normals each
  // primitive's triangles get flat vertices of their own, so compare positions.
  auto corners = [&](const Primitive& p) {
    std::vector<glm::vec3> out;
    for (std::uint32_t i : p.indices) out.push_back(asset.vertices(p)[i].position);
    return out;
  };
  const glm::vec3 v0(0, 0, 0), v1(1, 0, 0), v2(0, 1, 0), v3(1, 1, 0);
  EXPECT_EQ(corners(asset.meshes[0].primitives[0]), (std::vector<glm::vec3>{v0, v1, v2, v2, v1, v3}));
  EXPECT_EQ(corners(asset.meshes[0].primitives[1]), (std::vector<glm::vec3>{v0, v1, v2, v0, v2, v3}));
}

TEST_F(GltfDocument, AModelWithNoTrianglesIsEmptyWithWellDefinedBounds) {
  json doc = triangle_gltf();
  doc["meshes"][0]["primitives"][0]["mode"] = 0;  // points
  AssetManager assets;
  const ModelImport imported = import_gltf(write("points.gltf", doc), assets);
  EXPECT_TRUE(imported.bounds.empty);
  EXPECT_EQ(imported.bounds.min, glm::vec3(0.0f));
  EXPECT_EQ(imported.bounds.max, glm::vec3(0.0f));
  EXPECT_THAT(imported.warnings.at(0), HasSubstr("/meshes/0/primitives/0 draws points, not triangles, and is skipped"));
}

TEST_F(GltfDocument, OptionalExtensionsSayWhatIsLostAndRequiredOnesRefuse) {
  json doc = triangle_gltf();
  doc["extensionsUsed"] = {"KHR_materials_clearcoat", "EXT_something_new"};
  AssetManager assets;
  const ModelImport imported = import_gltf(write("optional.gltf", doc), assets);
  EXPECT_THAT(imported.warnings, ::testing::Contains(HasSubstr("ignores the optional extension KHR_materials_clearcoat: the clear-coat layer is not drawn")));
  EXPECT_THAT(imported.warnings, ::testing::Contains(HasSubstr("ignores the optional extension EXT_something_new, which Atrium does not know")));
  doc["extensionsRequired"] = {"KHR_materials_clearcoat"};
  EXPECT_THAT(refusal(write("required.gltf", doc)),
              HasSubstr("requires the extension KHR_materials_clearcoat, which Atrium does not support (the clear-coat layer is not drawn without it)"));
}

}  // namespace
}  // namespace atrium::assets
