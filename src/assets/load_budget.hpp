// What every importer shares: the one-line error that refuses a file, and the
// budget that refuses allocations a file's declared sizes would drive beyond
// the memory available, naming the file and the size instead of failing with
// std::bad_alloc.
#pragma once

#include <cstddef>
#include <filesystem>
#include <new>
#include <stdexcept>
#include <string>

#include "base/format.hpp"

namespace atrium::assets {

// "<file>: <problem>", one line: the file cannot be used.
class ImportError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Refuses allocations larger than the memory this load may use, before they
// are made: a file may declare any size, and a user must read the size and
// the file, not `std::bad_alloc`.
class MemoryBudget {
 public:
  // 0: the memory the system reports available (MemAvailable), read once.
  explicit MemoryBudget(std::size_t limit_bytes = 0);
  // Throws ImportError("<file>: <what> needs 12.0 GiB, more than ...").
  void require(std::size_t bytes, const std::string& what) const;
  // count * size, refused when it overflows or exceeds the budget.
  [[nodiscard]] std::size_t bytes(std::size_t count, std::size_t size, const std::string& what) const;
  [[nodiscard]] std::size_t limit() const { return limit_; }
  void set_file(std::string file) { file_ = std::move(file); }

 private:
  std::size_t limit_;
  std::string file_;
};

// Runs an importer's `load()`, turning the allocation failures that slip past
// the budget (the system running out anyway) into ImportError naming `path`.
template <typename Load>
auto refuse_out_of_memory(const std::filesystem::path& path, Load&& load) -> decltype(load()) {
  try {
    return load();
  } catch (const std::bad_alloc&) {
    throw ImportError(path.string() + ": out of memory while loading (the system refused an allocation)");
  } catch (const std::length_error&) {
    throw ImportError(path.string() + ": out of memory while loading (a size beyond what memory can hold)");
  }
}


}  // namespace atrium::assets
