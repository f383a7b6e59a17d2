// The one JSON reader behind glTF and scene files: pointers as RFC 6901 writes
// them, each kind of value refused in one phrasing, and both file types
// refusing the same mistake with the same words.
#include <filesystem>
#include <fstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "assets/asset_manager.hpp"
#include "assets/gltf_import.hpp"
#include "assets/json_reader.hpp"
#include "assets/load_budget.hpp"
#include "assets/scene_file.hpp"

namespace atrium::assets {
namespace {
namespace fs = std::filesystem;

// The message a read throws ("" when it reads).
template <class Read>
std::string refusal(Read read) {
  try {
    read();
  } catch (const JsonError& e) {
    return e.what();
  }
  return "";
}

TEST(JsonReader, PointersEscapeAsRfc6901Asks) {
  EXPECT_EQ(JsonPointer().str(), "/");
  EXPECT_EQ((JsonPointer() / "meshes" / 0 / "primitives").str(), "/meshes/0/primitives");
  EXPECT_EQ((JsonPointer() / "a/b" / "m~n").str(), "/a~1b/m~0n");
}

TEST(JsonReader, EachKindOfValueIsRefusedWithWhatWasExpectedAndWhatCame) {
  const JsonReader r("f.json");
  const Json doc = r.parse(R"({"s": 5, "n": "x", "big": 12, "frac": 1.5, "i": 7, "o": [], "b": 1, "v": [1, 2]})");
  const JsonPointer top;
  EXPECT_EQ(refusal([&] { (void)r.string(doc["s"], top / "s"); }), "f.json: /s: expected a string, got 5");
  EXPECT_EQ(refusal([&] { (void)r.number(doc["n"], top / "n"); }), "f.json: /n: expected a number, got \"x\"");
  EXPECT_EQ(refusal([&] { (void)r.number(doc["big"], top / "big", 0, 10, "a number from 0 to 10"); }),
            "f.json: /big: expected a number from 0 to 10, got 12");
  EXPECT_EQ(refusal([&] { (void)r.whole(doc["frac"], top / "frac", 0, 5000); }),
            "f.json: /frac: expected a whole number from 0 to 5,000, got 1.5");
  EXPECT_EQ(refusal([&] { (void)r.index(doc["i"], top / "i", 2, top / "accessors"); }),
            "f.json: /i: refers to /accessors/7, which does not exist (the file has 2)");
  EXPECT_EQ(refusal([&] { (void)r.object(doc["o"], top / "o"); }), "f.json: /o: expected an object, got []");
  EXPECT_EQ(refusal([&] { (void)r.boolean(doc["b"], top / "b"); }), "f.json: /b: expected true or false, got 1");
  EXPECT_EQ(refusal([&] { (void)r.numbers<3>(doc["v"], top / "v"); }), "f.json: /v: expected an array of 3 numbers, got [1,2]");
  EXPECT_EQ(refusal([&] { (void)r.required(doc, top, "missing"); }), "f.json: /missing: is missing");
  EXPECT_EQ(refusal([&] { r.only_keys(doc, top, {"s", "n", "big", "frac", "i", "o", "b"}); }),
            "f.json: /v: unknown key (expected one of: s, n, big, frac, i, o, b)");
  EXPECT_EQ(refusal([&] { (void)r.parse("{\"a\": }"); }).rfind("f.json: not valid JSON (", 0), 0u);
}

TEST(JsonReader, AbsentOptionalMembersGiveTheirFallbacks) {
  const JsonReader r("f.json");
  const Json doc = Json::parse(R"({"here": 2})");
  EXPECT_EQ(r.whole_or(doc, {}, "here", 0, 9, 5), 2u);
  EXPECT_EQ(r.whole_or(doc, {}, "gone", 0, 9, 5), 5u);
  EXPECT_EQ(r.string_or(doc, {}, "gone", "dflt"), "dflt");
  EXPECT_TRUE(r.array_or_empty(doc, {}, "gone").empty());
  EXPECT_TRUE(r.object_or_empty(doc, {}, "gone").empty());
}

// A string where a number belongs, in a glTF model and in a scene file: the
// same words after the pointer.
TEST(JsonReader, GltfAndSceneFilesRefuseTheSameMistakeAlike) {
  const fs::path folder = fs::temp_directory_path() / ("atrium_json_reader_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  std::ofstream(folder / "m.gltf") << R"({"asset": {"version": "2.0"}, "materials": [{"alphaCutoff": "half"}]})";
  std::ofstream(folder / "s.json") << R"({"exposure": "half"})";
  AssetManager assets;
  std::string gltf_message, scene_message;
  try {
    (void)import_gltf(folder / "m.gltf", assets);
  } catch (const ImportError& e) {
    gltf_message = e.what();
  }
  try {
    LoadReport report;
    (void)load_scene_file(folder / "s.json", assets, report);
  } catch (const SceneFileError& e) {
    scene_message = e.what();
  }
  EXPECT_EQ(gltf_message, (folder / "m.gltf").string() + ": /materials/0/alphaCutoff: expected a number, got \"half\"");
  EXPECT_EQ(scene_message, (folder / "s.json").string() + ": /exposure: expected a positive number, got \"half\"");
  fs::remove_all(folder);
}

}  // namespace
}  // namespace atrium::assets
