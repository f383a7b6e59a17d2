// Inputs the fuzzers once found or were seeded with (tests/fuzz/regressions):
// each must load or be refused with the loader's own error, never crash.
#include <filesystem>

#include <gtest/gtest.h>

#include "assets/gltf_import.hpp"
#include "assets/scene_file.hpp"

namespace atrium::assets {
namespace {

const std::filesystem::path kRegressions = std::filesystem::path(ATRIUM_SOURCE_DIR) / "tests/fuzz/regressions";

std::vector<std::filesystem::path> inputs(const char* target) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(kRegressions / target)) {
    if (entry.is_regular_file() && entry.path().filename() != ".gitkeep") files.push_back(entry.path());
  }
  return files;
}

TEST(FuzzRegressions, SceneFilesLoadOrAreRefused) {
  for (const auto& file : inputs("scene_file")) {
    AssetManager assets;
    LoadReport report;
    try {
      (void)load_scene_file(file, assets, report);
    } catch (const SceneFileError& e) {
      EXPECT_NE(std::string(e.what()).find(file.filename().string()), std::string::npos) << "the error names the file: " << e.what();
    } catch (const ImportError&) {
    }
  }
}

TEST(FuzzRegressions, GltfFilesImportOrAreRefused) {
  for (const auto& file : inputs("gltf")) {
    AssetManager assets;
    try {
      (void)import_gltf(file, assets);
    } catch (const ImportError& e) {
      EXPECT_NE(std::string(e.what()).find(file.filename().string()), std::string::npos) << "the error names the file: " << e.what();
    }
  }
}

}  // namespace
}  // namespace atrium::assets
