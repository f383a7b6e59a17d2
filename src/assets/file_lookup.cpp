#include "assets/file_lookup.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>

#include "assets/load_budget.hpp"

namespace atrium::assets {
namespace {

namespace fs = std::filesystem;

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// "/" + s, built in place: GCC 12 reports a false -Wrestrict overlap for
// operator+ of a literal and a string (its bug 105329).
std::string rooted(std::string s) {
  s.insert(s.begin(), '/');
  return s;
}

}  // namespace

std::string lowercase_extension(const fs::path& path) { return lower(path.extension().string()); }

FoundFile find_named_file(const fs::path& folder, const std::string& written) {
  std::string path = written;
  std::replace(path.begin(), path.end(), '\\', '/');
  // "C:/..." and "//server/..." are absolute on the machine that wrote them.
  const bool foreign_absolute = (path.size() > 2 && std::isalpha(static_cast<unsigned char>(path[0])) && path[1] == ':' && path[2] == '/') ||
                                path.starts_with("//");
  const bool absolute = foreign_absolute || fs::path(path).is_absolute();
  std::error_code ec;
  const fs::path direct = absolute ? fs::path(path) : folder / path;
  FoundFile result;
  if (!foreign_absolute && fs::is_regular_file(direct, ec)) {
    result.path = direct;
    if (path != written) result.how = "has Windows separators";
    return result;
  }
  // The same name in another letter case, or an absolute path from the
  // author's machine: look for the file name beside the model and below it,
  // preferring the file whose folders end the written path.
  const std::string wanted = lower(fs::path(path).filename().string());
  const std::string written_lower = rooted(lower(path));
  std::size_t best = 0;
  for (auto it = fs::recursive_directory_iterator(folder, fs::directory_options::skip_permission_denied, ec);
       !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    if (it.depth() > 4) it.disable_recursion_pending();
    if (!it->is_regular_file(ec) || lower(it->path().filename().string()) != wanted) continue;
    const std::string candidate = rooted(lower(fs::relative(it->path(), folder, ec).generic_string()));
    const std::size_t match = written_lower.ends_with(candidate) ? candidate.size() : 1;
    if (!result.path || match > best) {
      result.path = it->path();
      best = match;
    }
  }
  if (result.path) {
    result.how = absolute ? "is an absolute path from another machine"
                 : lower(path) == lower(fs::relative(*result.path, folder, ec).generic_string()) ? "differs in letter case from the file on disk"
                                                                                                  : "is not where the path says";
  }
  return result;
}

std::string found_elsewhere_warning(const std::string& written, const std::string& how, const fs::path& used, const fs::path& folder) {
  return "'" + written + "' " + how + "; " + used.lexically_relative(folder).generic_string() + " is used";
}

std::string unreadable_warning(const std::string& written, const std::string& problem) {
  return "'" + written + "', which it names, cannot be read (" + problem + ")";
}

std::string not_a_file(const fs::path& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec || status.type() == fs::file_type::not_found) return "no such file";
  if (status.type() == fs::file_type::directory) return "a directory";
  return "not a regular file";
}

FileBytes read_file_within(const fs::path& path, std::size_t limit) {
  FileBytes result;
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    result.problem = not_a_file(path);
    return result;
  }
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) {
    result.problem = "unreadable";
  } else if (size > limit) {
    result.problem = format_bytes(static_cast<double>(size)) + ", more than the memory available, " + format_bytes(static_cast<double>(limit));
  }
  if (!result.problem.empty()) return result;
  std::ifstream in(path, std::ios::binary);
  result.bytes.resize(static_cast<std::size_t>(size));
  in.read(reinterpret_cast<char*>(result.bytes.data()), static_cast<std::streamsize>(size));
  if (static_cast<std::size_t>(in.gcount()) != result.bytes.size()) {
    result.bytes.clear();
    result.problem = "unreadable";
  }
  return result;
}

}  // namespace atrium::assets
