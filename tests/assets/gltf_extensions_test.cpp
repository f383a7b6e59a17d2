// docs/gltf-extensions.md and the extension table (gltf_extensions.cpp) say
// the same: one row per extension, the same support and the same words.
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "assets/gltf_extensions.hpp"

namespace atrium::assets {
namespace {

TEST(GltfExtensions, TheDocsListEveryExtensionAsTheTableDoes) {
  std::ifstream in(std::filesystem::path(ATRIUM_SOURCE_DIR) / "docs/gltf-extensions.md");
  std::stringstream page;
  page << in.rdbuf();
  std::size_t rows = 0;
  for (std::string line; std::getline(page, line);) rows += line.rfind("| `", 0) == 0;
  EXPECT_EQ(rows, gltf_extensions().size()) << "one row per extension";
  for (const GltfExtension& e : gltf_extensions()) {
    const std::string row = "| `" + std::string(e.name) + "` | " + (e.supported ? "yes" : "no") + " | " + std::string(e.effect) + " |";
    EXPECT_NE(page.str().find(row), std::string::npos) << "missing or different: " << row;
  }
}

TEST(GltfExtensions, NamesAreUnique) {
  for (const GltfExtension& e : gltf_extensions()) EXPECT_EQ(find_gltf_extension(e.name), &e) << e.name;
  EXPECT_EQ(find_gltf_extension("EXT_not_a_thing"), nullptr);
}

}  // namespace
}  // namespace atrium::assets
