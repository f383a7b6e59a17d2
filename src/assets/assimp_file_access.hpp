// libassimp's file access, Atrium's way: every file assimp opens (the model,
// the parts a format keeps beside the model) is
// found as texture paths are (assets/file_lookup.hpp), checked (a regular
// file, within the load budget) and read whole into memory, so no handle stays
// open and nothing assimp opens escapes the budget. What could not be opened
// is kept, for one warning per file in Atrium's words.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include <assimp/IOSystem.hpp>

namespace atrium::assets {

class AssimpFileAccess : public Assimp::IOSystem {
 public:
  // `model`: the file being imported; the files it names are looked for
  // beside it. `limit`: the most bytes one file may have.
  AssimpFileAccess(std::filesystem::path model, std::size_t limit);

  bool Exists(const char* file) const override;
  [[nodiscard]] char getOsSeparator() const override { return '/'; }
  Assimp::IOStream* Open(const char* file, const char* mode = "rb") override;
  void Close(Assimp::IOStream* stream) override;

  // Each open, in order: the path assimp asked for, what was read (empty when
  // nothing was) and, when it failed, why ("no such file", "a directory").
  struct Access {
    std::string asked;
    std::filesystem::path read;
    std::string problem;
    std::string how;  // found elsewhere than the path says: why (file_lookup.hpp)
  };
  [[nodiscard]] const std::vector<Access>& accesses() const { return accesses_; }

  // One line per file the model named that could not be read, and per file
  // found elsewhere than its path says: "'x.bin', which it names, cannot be
  // read (no such file); what it holds is left out".
  [[nodiscard]] std::vector<std::string> warnings() const;

 private:
  // What `asked` resolves to: the path to read, or the problem.
  Access resolve(const std::string& asked) const;

  std::filesystem::path model_, folder_;
  std::size_t limit_;
  std::vector<Access> accesses_;
};

}  // namespace atrium::assets
