// The binding table (src/render/binding_slots.hpp) against its twin, the
// `layout(binding = N)` of every block in every shader: each block the
// frame's shaders declare is in the table, at its slot.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "render/binding_slots.hpp"

namespace atrium {
namespace {
namespace fs = std::filesystem;

TEST(BindingSlots, EveryShaderBlockIsAtItsSlot) {
  const std::regex block(R"(layout\((?:std430|std140),\s*binding\s*=\s*(\d+)\)[^;{]*?\b(?:buffer|uniform)\s+(\w+))");
  std::size_t blocks = 0;
  for (const auto& entry : fs::recursive_directory_iterator(ATRIUM_SHADER_DIR)) {
    if (!entry.is_regular_file()) continue;
    const std::string relative = fs::relative(entry.path(), ATRIUM_SHADER_DIR).generic_string();
    if (relative.starts_with("probe/")) continue;  // the GPU probe's programs run outside the frame (gfx/stage_probe.cpp)
    std::ifstream in(entry.path());
    std::stringstream text;
    text << in.rdbuf();
    const std::string source = text.str();
    for (auto it = std::sregex_iterator(source.begin(), source.end(), block); it != std::sregex_iterator(); ++it) {
      ++blocks;
      const std::string name = (*it)[2];
      const unsigned binding = static_cast<unsigned>(std::stoul((*it)[1]));
      const auto* slot = std::find_if(std::begin(render::kBlockSlots), std::end(render::kBlockSlots),
                                      [&](const render::BlockSlot& s) { return s.block == name; });
      if (slot == std::end(render::kBlockSlots)) {
        ADD_FAILURE() << relative << ": block " << name << " is not in render/binding_slots.hpp";
        continue;
      }
      EXPECT_EQ(binding, slot->binding) << relative << ": block " << name;
    }
  }
  EXPECT_GE(blocks, std::size(render::kBlockSlots)) << "every row's block is declared somewhere";
}

}  // namespace
}  // namespace atrium
