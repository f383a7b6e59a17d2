#include "assets/assimp_file_access.hpp"

#include <vector>

#include <assimp/MemoryIOWrapper.h>

#include "assets/fbx_sizes.hpp"
#include "assets/file_lookup.hpp"

namespace atrium::assets {
namespace {

namespace fs = std::filesystem;

// A stream over bytes it owns (assimp's MemoryIOStream only borrows them):
// the holder comes first, so the bytes exist before the stream points at them.
struct OwnedBytes {
  std::vector<std::uint8_t> bytes;
};
// An empty file still gets a valid pointer: the stream copies from it (zero
// bytes), and memcpy from a null pointer is undefined even then.
constexpr std::uint8_t kNoBytes = 0;
struct OwnedMemoryStream : OwnedBytes, Assimp::MemoryIOStream {
  explicit OwnedMemoryStream(std::vector<std::uint8_t> data)
      : OwnedBytes{std::move(data)}, Assimp::MemoryIOStream(bytes.empty() ? &kNoBytes : bytes.data(), bytes.size(), false) {}
};

}  // namespace

AssimpFileAccess::AssimpFileAccess(fs::path model, std::size_t limit)
    : model_(std::move(model)),
      folder_(model_.parent_path().empty() ? fs::path(".") : model_.parent_path()),
      limit_(limit) {}

AssimpFileAccess::Access AssimpFileAccess::resolve(const std::string& asked) const {
  Access access{asked, {}, {}, {}};
  const fs::path path(asked);
  std::error_code ec;
  if (path == model_ || fs::is_regular_file(path, ec)) {
    access.read = path;
  } else {
    // assimp joins the model's folder and the name the file wrote: look the
    // name up as a texture's would be, relative to the model's folder.
    const std::string folder = folder_.string() + "/";
    const std::string written = asked.starts_with(folder) ? asked.substr(folder.size()) : asked;
    FoundFile found = find_named_file(folder_, written);
    if (!found.path) {
      access.problem = not_a_file(path);
      return access;
    }
    access.read = *found.path;
    access.how = std::move(found.how);
  }
  if (!fs::is_regular_file(access.read, ec)) {
    access.problem = not_a_file(access.read);
    access.read.clear();
  }
  return access;
}

bool AssimpFileAccess::Exists(const char* file) const { return file && resolve(file).problem.empty(); }

Assimp::IOStream* AssimpFileAccess::Open(const char* file, const char* mode) {
  if (!file) return nullptr;
  Access access = resolve(file);
  // Atrium only reads; a request to write is refused like a missing file.
  if (access.problem.empty() && mode && std::string_view(mode).find_first_of("wa+") != std::string_view::npos) {
    access.problem = "opened for writing, which Atrium never does";
    access.read.clear();
  }
  FileBytes read;
  if (access.problem.empty()) {
    read = read_file_within(access.read, limit_);
    access.problem = read.problem.empty() ? fbx_array_size_problem(read.bytes, limit_) : read.problem;
  }
  if (!access.problem.empty()) access.read.clear();
  const bool ok = access.problem.empty();
  accesses_.push_back(std::move(access));
  if (!ok) return nullptr;
  // The stream owns the bytes; Close deletes both.
  return new OwnedMemoryStream(std::move(read.bytes));
}

void AssimpFileAccess::Close(Assimp::IOStream* stream) { delete stream; }

std::vector<std::string> AssimpFileAccess::warnings() const {
  std::vector<std::string> lines;
  std::vector<std::string> told;
  for (std::size_t i = 0; i < accesses_.size(); ++i) {
    const Access& a = accesses_[i];
    if (fs::path(a.asked) == model_) continue;  // the model itself: a failure there refuses the file
    if (std::find(told.begin(), told.end(), a.asked) != told.end()) continue;
    told.push_back(a.asked);
    const fs::path shown = fs::path(a.asked).lexically_relative(folder_);
    const std::string name = shown.empty() || shown.string().starts_with("..") ? a.asked : shown.generic_string();
    if (a.problem.empty()) {
      if (!a.how.empty()) lines.push_back(found_elsewhere_warning(name, a.how, a.read, folder_));
      continue;
    }
    std::string line = unreadable_warning(name, a.problem);
    if (i + 1 < accesses_.size() && accesses_[i + 1].problem.empty() && fs::path(accesses_[i + 1].asked) != model_) {
      line += "; '" + accesses_[i + 1].read.lexically_relative(folder_).generic_string() + "' is used instead";
    } else {
      line += "; what it holds is left out";
    }
    lines.push_back(std::move(line));
  }
  return lines;
}

}  // namespace atrium::assets
