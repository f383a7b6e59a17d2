#include "assets/fbx_sizes.hpp"

#include <algorithm>
#include <cstring>
#include <vector>

#include <zlib.h>

#include "assets/byte_order.hpp"
#include "assets/load_budget.hpp"

namespace atrium::assets {
namespace {

constexpr char kMagic[] = "Kaydara FBX Binary  ";
// zlib's deflate expands at most 1032:1 (RFC 1951 blocks of 258-byte matches).
constexpr std::uint64_t kInflateRatio = 1032;

std::size_t element_size(std::uint8_t type) {
  switch (type) {
    case 'f': case 'i': return 4;
    case 'd': case 'l': return 8;
    case 'b': return 1;
    default: return 0;
  }
}

// Whether zlib inflates `stored` bytes into `declared` without an error, as
// libassimp's reader asks (Z_OK or Z_STREAM_END).
bool inflates(const std::uint8_t* stored, std::size_t stored_size, std::size_t declared, std::vector<std::uint8_t>& scratch) {
  scratch.resize(std::max<std::size_t>(declared, 1));
  z_stream stream{};
  if (inflateInit(&stream) != Z_OK) return false;
  stream.next_in = const_cast<Bytef*>(stored);
  stream.avail_in = static_cast<uInt>(stored_size);
  stream.next_out = scratch.data();
  stream.avail_out = static_cast<uInt>(declared);
  const int status = inflate(&stream, Z_FINISH);
  inflateEnd(&stream);
  return status == Z_STREAM_END || status == Z_OK;
}

}  // namespace

std::string fbx_array_size_problem(std::span<const std::uint8_t> bytes, std::size_t limit) {
  if (bytes.size() < 27 || std::memcmp(bytes.data(), kMagic, sizeof kMagic - 1) != 0) return {};
  const std::uint64_t version = read_le(bytes, 23, 4);
  // Node headers: end offset, property count, property bytes (32 bits before
  // version 7500, 64 after), then the name's length and the name.
  const std::size_t word = version >= 7500 ? 8 : 4;
  std::vector<std::pair<std::uint64_t, std::uint64_t>> pending{{27, bytes.size()}};  // node lists: [begin, end)
  std::vector<std::uint8_t> scratch;
  while (!pending.empty()) {
    auto [at, end] = pending.back();
    pending.pop_back();
    while (at + 3 * word + 1 <= end) {
      const std::uint64_t node_end = read_le(bytes, at, word);
      if (node_end == 0) break;  // the null record that closes a list
      const std::uint64_t property_bytes = read_le(bytes, at + 2 * word, word);
      const std::uint64_t name_length = bytes[at + 3 * word];
      const std::uint64_t properties = at + 3 * word + 1 + name_length;
      // Structure out of bounds: libassimp reports that itself.
      if (node_end <= at || node_end > end || properties > node_end || property_bytes > node_end - properties) return {};
      for (std::uint64_t p = properties; p < properties + property_bytes;) {
        const std::uint8_t type = bytes[p];
        const std::size_t size = element_size(type);
        if (size == 0) {
          const std::size_t scalar = type == 'Y' ? 2 : type == 'C' ? 1 : type == 'I' || type == 'F' ? 4 : type == 'D' || type == 'L' ? 8 : 0;
          if (scalar) {
            p += 1 + scalar;
          } else if ((type == 'S' || type == 'R') && p + 5 <= node_end) {
            p += 5 + read_le(bytes, p + 1, 4);
          } else {
            return {};
          }
          continue;
        }
        if (p + 13 > node_end) return {};
        const std::uint64_t count = read_le(bytes, p + 1, 4), encoding = read_le(bytes, p + 5, 4), stored = read_le(bytes, p + 9, 4);
        const std::uint64_t declared = count * size;
        const std::string name(reinterpret_cast<const char*>(&bytes[at + 3 * word + 1]), name_length);
        const std::string what = "its array '" + name + "' at byte " + std::to_string(p) + " declares " + std::to_string(count) + " values (" +
                                 format_bytes(static_cast<double>(declared)) + ")";
        if (declared > limit) return what + ", more than the memory available, " + format_bytes(static_cast<double>(limit));
        if (encoding == 1 && declared > stored * kInflateRatio + 64) {
          return what + " from " + std::to_string(stored) + " compressed bytes, more than zlib can inflate them to";
        }
        if (p + 13 + stored > node_end) return {};
        if (encoding == 1 && !inflates(&bytes[p + 13], stored, declared, scratch)) return what + " whose compressed bytes do not inflate";
        p += 13 + stored;
      }
      if (properties + property_bytes < node_end) pending.emplace_back(properties + property_bytes, node_end);
      at = node_end;
    }
  }
  return {};
}

}  // namespace atrium::assets
