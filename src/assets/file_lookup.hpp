// Finds the files a model names (textures, material libraries, external
// parts) the way exporters write their paths: Windows separators, another
// letter case than on disk, absolute paths from the author's machine (looked up
// beside the model and in the folders below it), and reads them whole within
// the load budget. Every importer that opens a file a model names goes through
// here, so they all agree on what is found and what is refused.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace atrium::assets {

struct FoundFile {
  std::optional<std::filesystem::path> path;  // nullopt: not found
  // Empty when found where the path says; otherwise why it was looked for
  // elsewhere ("differs in letter case from the file on disk"), for a warning.
  std::string how;
};

// `written` as the model wrote it, relative to `folder` (the model's folder)
// unless absolute.
// A path's extension in lower case (".obj" for "Model.OBJ"), as formats are told apart.
[[nodiscard]] std::string lowercase_extension(const std::filesystem::path& path);

[[nodiscard]] FoundFile find_named_file(const std::filesystem::path& folder, const std::string& written);

// The warnings every importer gives for a file a model names, in one wording:
// found elsewhere than its path says ("'textures\\a.png' has Windows separators;
// textures/a.png is used", `used` shown relative to the model's folder), and
// not readable ("'a.mtl', which it names, cannot be read (no such file)", to
// which the caller adds what happens instead).
[[nodiscard]] std::string found_elsewhere_warning(const std::string& written, const std::string& how, const std::filesystem::path& used,
                                                  const std::filesystem::path& folder);
[[nodiscard]] std::string unreadable_warning(const std::string& written, const std::string& problem);

// What a path names when it is not a regular file, in a few words: "no such
// file", "a directory", "not a regular file".
[[nodiscard]] std::string not_a_file(const std::filesystem::path& path);

// A file's bytes, read whole; `problem` empty, or why nothing was read ("no
// such file", "unreadable", "3.0 GiB, more than the memory available, 2.0 GiB").
struct FileBytes {
  std::vector<std::uint8_t> bytes;
  std::string problem;
};
[[nodiscard]] FileBytes read_file_within(const std::filesystem::path& path, std::size_t limit);

}  // namespace atrium::assets
