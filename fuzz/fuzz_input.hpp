// Fuzz inputs reach the loaders the way users' files do: as a file on disk.
// Each process writes its inputs to one private temporary file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace atrium::fuzz {

inline std::filesystem::path write_input(const std::uint8_t* data, std::size_t size, const std::string& extension) {
  static const std::filesystem::path folder = [] {
    auto path = std::filesystem::temp_directory_path() / ("atrium_fuzz_" + std::to_string(::getpid()));
    std::filesystem::create_directories(path);
    return path;
  }();
  const std::filesystem::path file = folder / ("input" + extension);
  std::ofstream(file, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return file;
}

}  // namespace atrium::fuzz
