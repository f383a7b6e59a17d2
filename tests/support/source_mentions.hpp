// How the tests hold a feature to its own files: every file under src/ and
// shaders/, outside the feature's own folders, whose lines mention a word
// (case-insensitively), with how many lines do.
#pragma once

#include <cctype>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <map>
#include <string>
#include <string_view>

namespace atrium::testing {

inline std::map<std::string, int> mentions_outside(std::string_view word, std::initializer_list<std::string_view> own_folders) {
  namespace fs = std::filesystem;
  const fs::path root(ATRIUM_SOURCE_DIR);
  std::map<std::string, int> outside;
  for (const char* top : {"src", "shaders"}) {
    for (const auto& entry : fs::recursive_directory_iterator(root / top)) {
      if (!entry.is_regular_file()) continue;
      const std::string relative = fs::relative(entry.path(), root).generic_string();
      bool own = false;
      for (const std::string_view folder : own_folders) own = own || relative.starts_with(folder);
      if (own) continue;
      std::ifstream in(entry.path());
      for (std::string line; std::getline(in, line);) {
        for (char& c : line) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        if (line.find(word) != std::string::npos) ++outside[relative];
      }
    }
  }
  return outside;
}

}  // namespace atrium::testing
