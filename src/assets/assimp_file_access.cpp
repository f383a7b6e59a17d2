#include "assets/assimp_file_access.hpp"

#include <algorithm>
#include <fstream>
#include <memory>

#include <assimp/MemoryIOWrapper.h>

#include "assets/fbx_sizes.hpp"
#include "assets/file_lookup.hpp"
#include "assets/load_budget.hpp"

namespace atrium::assets {
namespace {

namespace fs = std::filesystem;

// What a path names when it is not a regular file, in a few words.
std::string not_a_file(const fs::path& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec || status.type() == fs::file_type::not_found) return "no such file";
  if (status.type() == fs::file_type::directory) return "a directory";
  return "not a regular file";
}

}  // namespace

AssimpFileAccess::AssimpFileAccess(fs::path model, std::size_t limit)
    : model_(std::move(model)), folder_(model_.parent_path().empty() ? fs::path(".") : model_.parent_path()), limit_(limit) {}

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
    return access;
  }
  const std::uintmax_t size = fs::file_size(access.read, ec);
  if (ec) {
    access.problem = "unreadable";
  } else if (size > limit_) {
    access.problem = format_bytes(static_cast<double>(size)) + ", more than the memory available, " + format_bytes(static_cast<double>(limit_));
  }
  if (!access.problem.empty()) access.read.clear();
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
  std::unique_ptr<std::uint8_t[]> bytes;
  std::size_t size = 0;
  if (access.problem.empty()) {
    std::error_code ec;
    size = static_cast<std::size_t>(fs::file_size(access.read, ec));
    std::ifstream in(access.read, std::ios::binary);
    bytes.reset(new std::uint8_t[std::max<std::size_t>(size, 1)]);
    in.read(reinterpret_cast<char*>(bytes.get()), static_cast<std::streamsize>(size));
    if (ec || static_cast<std::size_t>(in.gcount()) != size) {
      access.problem = "unreadable";
    } else {
      access.problem = fbx_array_size_problem({bytes.get(), size}, limit_);
    }
  }
  const bool ok = access.problem.empty();
  accesses_.push_back(std::move(access));
  if (!ok) return nullptr;
  // The stream owns the bytes; Close deletes both.
  return new Assimp::MemoryIOStream(bytes.release(), size, true);
}

void AssimpFileAccess::Close(Assimp::IOStream* stream) { delete stream; }

std::vector<std::string> AssimpFileAccess::warnings() const {
  std::vector<std::string> lines;
  std::vector<std::string> told;
  const std::string stem = (folder_ / model_.stem()).string();
  for (std::size_t i = 0; i < accesses_.size(); ++i) {
    const Access& a = accesses_[i];
    if (fs::path(a.asked) == model_) continue;  // the model itself: a failure there refuses the file
    if (std::find(told.begin(), told.end(), a.asked) != told.end()) continue;
    told.push_back(a.asked);
    const fs::path shown = fs::path(a.asked).lexically_relative(folder_);
    const std::string name = shown.empty() || shown.string().starts_with("..") ? a.asked : shown.generic_string();
    if (a.problem.empty()) {
      if (!a.how.empty()) lines.push_back("'" + name + "' " + a.how + "; " + a.read.lexically_relative(folder_).generic_string() + " is used");
      continue;
    }
    // assimp's OBJ reader, missing the library a file names, tries
    // <model>.mtl on its own: not a file the user wrote, so no word of it.
    if (i > 0 && !accesses_[i - 1].problem.empty() && a.asked.starts_with(stem) && a.asked.size() == stem.size() + 4) continue;
    std::string line = "'" + name + "', which it names, cannot be read (" + a.problem + ")";
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
