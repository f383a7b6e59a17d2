// Little-endian words in file formats read byte by byte (BMP headers, binary
// FBX), so that the host's byte order and alignment never matter.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

namespace atrium::assets {

// The `size`-byte (at most 8) little-endian word at `at`; the caller has checked the bounds.
inline std::uint64_t read_le(std::span<const std::uint8_t> bytes, std::size_t at, std::size_t size) {
  std::uint64_t value = 0;
  for (std::size_t i = 0; i < size; ++i) value |= static_cast<std::uint64_t>(bytes[at + i]) << (8 * i);
  return value;
}

}  // namespace atrium::assets
