#include "assets/load_budget.hpp"

#include <cstdio>
#include <fstream>
#include <limits>

namespace atrium::assets {
namespace {

std::size_t memory_available() {
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  std::size_t kib = 0;
  std::string unit;
  while (meminfo >> key >> kib >> unit) {
    if (key == "MemAvailable:") return kib * 1024;
  }
  return std::numeric_limits<std::size_t>::max();
}

}  // namespace

MemoryBudget::MemoryBudget(std::size_t limit_bytes) : limit_(limit_bytes ? limit_bytes : memory_available()) {}

void MemoryBudget::require(std::size_t bytes, const std::string& what) const {
  if (bytes <= limit_) return;
  throw ImportError(file_ + ": " + what + " needs " + format_bytes(static_cast<double>(bytes)) + ", more than the " +
                    format_bytes(static_cast<double>(limit_)) + " of memory available");
}

std::size_t MemoryBudget::bytes(std::size_t count, std::size_t size, const std::string& what) const {
  if (size != 0 && count > std::numeric_limits<std::size_t>::max() / size) {
    throw ImportError(file_ + ": " + what + " needs " + std::to_string(count) + " x " + std::to_string(size) + " bytes, more than memory can hold");
  }
  require(count * size, what);
  return count * size;
}

}  // namespace atrium::assets
