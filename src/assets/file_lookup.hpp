// Finds the files a model names (textures, material libraries, external
// parts) the way exporters write their paths: Windows separators, another
// letter case than on disk, absolute paths from the author's machine (looked up
// beside the model and in the folders below it). Every importer that opens a
// file a model names goes through here, so they all agree on what is found.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace atrium::assets {

struct FoundFile {
  std::optional<std::filesystem::path> path;  // nullopt: not found
  // Empty when found where the path says; otherwise why it was looked for
  // elsewhere ("differs in letter case from the file on disk"), for a warning.
  std::string how;
};

// `written` as the model wrote it, relative to `folder` (the model's folder)
// unless absolute.
[[nodiscard]] FoundFile find_named_file(const std::filesystem::path& folder, const std::string& written);

}  // namespace atrium::assets
