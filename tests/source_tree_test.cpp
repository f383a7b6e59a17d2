// The rules of docs/architecture.md that a compiler does not check, checked
// on the source tree: namespaces follow folders, includes point only down the
// layers, and the frame's long-lived GL objects are named only by their owner
// (passes reach them through the frame graph's PassResources).
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace atrium {
namespace {

namespace fs = std::filesystem;

struct SourceFile {
  std::string path;  // relative to the repository, e.g. "src/render/frame/draw_list.hpp"
  std::vector<std::string> lines;
};

std::vector<SourceFile> sources() {
  const fs::path root(ATRIUM_SOURCE_DIR);
  std::vector<SourceFile> files;
  for (const auto& entry : fs::recursive_directory_iterator(root / "src")) {
    const std::string extension = entry.path().extension().string();
    if (!entry.is_regular_file() || (extension != ".hpp" && extension != ".cpp")) continue;
    SourceFile file{fs::relative(entry.path(), root).generic_string(), {}};
    std::ifstream in(entry.path());
    for (std::string line; std::getline(in, line);) file.lines.push_back(line);
    files.push_back(std::move(file));
  }
  EXPECT_GT(files.size(), 100u) << "the source tree was not found at " << ATRIUM_SOURCE_DIR;
  return files;
}

bool under(const std::string& path, const std::string& folder) { return path.starts_with(folder); }

// The namespace a file in `path` declares its names in.
std::string namespace_of_folder(const std::string& path) {
  // The families of src/render with a namespace of their own, then the layers.
  static const std::vector<std::pair<std::string, std::string>> kFolders = {
      {"src/render/lighting/", "atrium::lighting"}, {"src/render/shadows/", "atrium::shadows"},
      {"src/render/techniques/", "atrium::techniques"}, {"src/render/", "atrium::render"},
      {"src/ecs/", "atrium::ecs"}, {"src/assets/", "atrium::assets"}, {"src/gfx/", "atrium::gfx"},
  };
  for (const auto& [folder, name] : kFolders) {
    if (under(path, folder)) return name;
  }
  return "atrium";  // base, components, systems, app
}

TEST(SourceTree, NamespacesFollowFolders) {
  const std::regex opening(R"(^namespace (atrium(::\w+)*) \{)");
  int checked = 0;
  for (const SourceFile& file : sources()) {
    const std::string expected = namespace_of_folder(file.path);
    for (std::size_t i = 0; i < file.lines.size(); ++i) {
      std::smatch match;
      if (!std::regex_search(file.lines[i], match, opening)) continue;
      const std::string found = match[1];
      // A nested namespace of the folder's own (atrium::assets::gltf) is the folder's.
      const bool ok = found == expected || found.starts_with(expected + "::");
      EXPECT_TRUE(ok) << file.path << ":" << i + 1 << " declares namespace " << found << "; its folder's is " << expected;
      ++checked;
    }
  }
  EXPECT_GT(checked, 100);
}

// Which top folders of src/ a folder may include from: each layer from the
// ones below it (docs/architecture.md), never the other way.
TEST(SourceTree, IncludesPointDownTheLayers) {
  const std::map<std::string, std::set<std::string>> kAllowed = {
      {"base", {"base"}},
      {"ecs", {"ecs", "base"}},
      {"gfx", {"gfx", "base"}},
      {"assets", {"assets", "components", "ecs", "base"}},
      {"components", {"components", "assets", "ecs", "base"}},
      {"render", {"render", "gfx", "assets", "components", "ecs", "base"}},
      {"systems", {"systems", "render", "gfx", "assets", "components", "ecs", "base"}},
      {"app", {"app", "systems", "render", "gfx", "assets", "components", "ecs", "base"}},
  };
  const std::regex include(R"re(^#include "(\w+)/)re");
  for (const SourceFile& file : sources()) {
    const std::string layer = file.path.substr(4, file.path.find('/', 4) - 4);
    const auto allowed = kAllowed.find(layer);
    ASSERT_NE(allowed, kAllowed.end()) << file.path << ": a top folder of src/ this test does not know";
    for (std::size_t i = 0; i < file.lines.size(); ++i) {
      std::smatch match;
      if (!std::regex_search(file.lines[i], match, include)) continue;
      EXPECT_TRUE(allowed->second.contains(match[1])) << file.path << ":" << i + 1 << " includes from " << match[1] << "/";
      // Within render: a technique is chosen by the renderer alone (systems and
      // the app name them too); the rest of the frame is technique-agnostic.
      if (file.lines[i].find("\"render/techniques/") != std::string::npos) {
        EXPECT_TRUE(under(file.path, "src/render/techniques/") || under(file.path, "src/render/mesh_renderer.") || layer == "app" ||
                    layer == "systems")
            << file.path << ":" << i + 1 << " includes a technique's header";
      }
    }
  }
}

// The frame's long-lived GL objects and the files that may name them: their
// owner, which imports them into each frame's graph. Every pass reaches them
// through PassResources (res.texture, res.buffer, res.framebuffer).
TEST(SourceTree, FrameTargetsAreNamedOnlyByTheirOwner) {
  struct Owned {
    std::string token;
    std::vector<std::string> owners;
  };
  const std::vector<Owned> kOwned = {
      {"hdr_color_", {"src/render/mesh_renderer."}},
      {"depth_stencil_", {"src/render/mesh_renderer."}},
      {"output_color_", {"src/render/mesh_renderer."}},
      {"diffuse_light_", {"src/render/mesh_renderer."}},
      {"specular_light_", {"src/render/mesh_renderer."}},
      // The shadow atlas: drawn by its own module, imported by the renderer.
      {"shadows_.texture()", {"src/render/mesh_renderer.", "src/render/shadows/"}},
      {"atlas_.id()", {"src/render/shadows/"}},
      // The frame's draw buffers (FrameDraws::import_into); the shadow atlas's
      // casters have buffers of the same names, its own.
      {"instances_.buffer", {"src/render/frame/frame_draws.", "src/render/shadows/"}},
      {"materials_.buffer", {"src/render/frame/frame_draws.", "src/render/shadows/"}},
      {"commands_.buffer", {"src/render/frame/frame_draws.", "src/render/shadows/"}},
  };
  for (const SourceFile& file : sources()) {
    for (const Owned& owned : kOwned) {
      bool owner = false;
      for (const std::string& folder : owned.owners) owner = owner || under(file.path, folder);
      if (owner) continue;
      for (std::size_t i = 0; i < file.lines.size(); ++i) {
        const std::string& line = file.lines[i];
        const std::size_t at = line.find(owned.token);
        // A longer name that ends in the token (caster_instances_) is another object.
        const bool found = at != std::string::npos && (at == 0 || !(std::isalnum(static_cast<unsigned char>(line[at - 1])) || line[at - 1] == '_'));
        EXPECT_FALSE(found) << file.path << ":" << i + 1 << " names " << owned.token << ", which only its owner may: "
                            << "declare it in a pass and reach it through PassResources";
      }
    }
  }
}

}  // namespace
}  // namespace atrium
