#include "assets/mtl_check.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <string_view>

namespace atrium::assets {
namespace {

// The statements libassimp's MTL reader takes as textures (it compares them
// case-insensitively): every map_ statement, and the bump, displacement and
// normal maps' short names.
constexpr std::array<std::string_view, 4> kTextureStatements = {"map_", "bump", "disp", "norm"};
// What ends a line for libassimp's reader: NUL and form feed as well as CR and LF.
constexpr std::string_view kLineEnds("\r\n\0\f", 4);

bool starts_with_nocase(std::string_view line, std::string_view prefix) {
  return line.size() >= prefix.size() && std::equal(prefix.begin(), prefix.end(), line.begin(), [](char a, char b) {
           return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b));
         });
}

}  // namespace

std::string mtl_texture_before_material_problem(std::span<const std::uint8_t> bytes) {
  const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  std::size_t number = 0;
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t end = std::min(text.find_first_of(kLineEnds, at), text.size());
    std::string_view line = text.substr(at, end - at);
    at = end + (text.substr(end, 2) == "\r\n" ? 2 : 1);
    ++number;
    while (!line.empty() && (line.front() == ' ' || line.front() == '\t')) line.remove_prefix(1);
    if (starts_with_nocase(line, "newmtl")) return {};
    for (const std::string_view statement : kTextureStatements) {
      if (!starts_with_nocase(line, statement)) continue;
      const std::string_view keyword = line.substr(0, std::min(line.find_first_of(" \t"), line.size()));
      return "its line " + std::to_string(number) + " gives a texture ('" + std::string(keyword.substr(0, 32)) +
             "') before any 'newmtl' names a material to give it to";
    }
  }
  return {};
}

}  // namespace atrium::assets
