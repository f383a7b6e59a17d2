#include "assets/fbx_sizes.hpp"

#include <algorithm>
#include <cstring>
#include <vector>

#include <zlib.h>

#include "assets/byte_order.hpp"
#include "assets/load_budget.hpp"

namespace atrium::assets {
namespace {

// libassimp 5.2.5 compares the first 18 bytes only ("Kaydara FBX Binary"),
// so this walk must too: a file it takes for FBX is a file it inflates.
constexpr char kMagic[] = "Kaydara FBX Binary";
// zlib's deflate expands at most 1032:1 (RFC 1951 blocks of 258-byte matches).
constexpr std::uint64_t kInflateRatio = 1032;

// How libassimp's tokenizer reads a property of each type code: one value of
// `size` bytes, a string or raw block after its 32-bit length, an array of
// `size`-byte values after its three-word header (size 0: byte arrays, which
// no reader of libassimp's inflates), or, for 'b', the rest of its node's
// properties. A type it does not know stops the tokenizer.
struct PropertyLayout {
  enum Kind { kUnknown, kValue, kSized, kArray, kRestOfNode } kind = kUnknown;
  std::size_t size = 0;
};

PropertyLayout layout_of(std::uint8_t type) {
  switch (type) {
    case 'C': return {PropertyLayout::kValue, 1};
    case 'Y': return {PropertyLayout::kValue, 2};
    case 'I': case 'F': return {PropertyLayout::kValue, 4};
    case 'D': case 'L': return {PropertyLayout::kValue, 8};
    case 'S': case 'R': return {PropertyLayout::kSized, 0};
    case 'c': return {PropertyLayout::kArray, 0};
    case 'f': case 'i': return {PropertyLayout::kArray, 4};
    case 'd': case 'l': return {PropertyLayout::kArray, 8};
    case 'b': return {PropertyLayout::kRestOfNode, 0};
    default: return {};
  }
}

// Whether zlib inflates `stored` bytes into `declared` without an error, as
// libassimp's reader asks (Z_OK or Z_STREAM_END, into a buffer of the
// declared size in 32 bits, as it computes it).
bool inflates(const std::uint8_t* stored, std::size_t stored_size, std::uint32_t declared, std::vector<std::uint8_t>& scratch) {
  scratch.resize(std::max<std::size_t>(declared, 1));
  z_stream stream{};
  if (inflateInit(&stream) != Z_OK) return false;
  stream.next_in = const_cast<Bytef*>(stored);
  stream.avail_in = static_cast<uInt>(stored_size);
  stream.next_out = scratch.data();
  stream.avail_out = declared;
  const int status = inflate(&stream, Z_FINISH);
  inflateEnd(&stream);
  return status == Z_STREAM_END || status == Z_OK;
}

// A list of node records: [begin, end), and whether it is nested in a node
// (libassimp skips a zero word there and reads on; at the top it stops).
struct NodeList {
  std::uint64_t begin, end;
  bool nested;
};

}  // namespace

// The walk follows libassimp's binary tokenizer (FBXBinaryTokenizer.cpp,
// ReadScope and ReadData) record for record. Where the tokenizer would stop on
// a structural error it returns nothing: libassimp then refuses the file
// before inflating anything. It must never stop where the tokenizer reads on,
// or an array after that point would reach libassimp unchecked.
std::string fbx_array_size_problem(std::span<const std::uint8_t> bytes, std::size_t limit) {
  if (bytes.size() < 27 || std::memcmp(bytes.data(), kMagic, sizeof kMagic - 1) != 0) return {};
  const std::uint64_t version = read_le(bytes, 23, 4);
  // Node headers: end offset, property count, property bytes (32 bits before
  // version 7500, 64 after), then the name's length and the name. A node with
  // children ends in a null record of three words and a byte.
  const std::size_t word = version >= 7500 ? 8 : 4;
  const std::uint64_t null_record = 3 * word + 1;
  std::vector<NodeList> pending{{27, bytes.size(), false}};
  std::vector<std::uint8_t> scratch;
  while (!pending.empty()) {
    const NodeList list = pending.back();
    pending.pop_back();
    for (std::uint64_t at = list.begin; at < list.end;) {
      if (at + word > list.end) return {};
      const std::uint64_t node_end = read_le(bytes, at, word);
      if (node_end == 0) {
        if (!list.nested) break;  // the top level's closing record
        at += word;
        continue;
      }
      if (at + null_record > list.end) return {};
      const std::uint64_t property_bytes = read_le(bytes, at + 2 * word, word);
      const std::uint64_t name_length = bytes[at + 3 * word];
      const std::uint64_t properties = at + null_record + name_length;
      // Structure out of bounds: libassimp reports that itself.
      if (node_end <= at || node_end > list.end || properties > node_end || property_bytes > node_end - properties) return {};
      const std::uint64_t properties_end = properties + property_bytes;
      for (std::uint64_t p = properties; p < properties_end;) {
        const PropertyLayout layout = layout_of(bytes[p]);
        if (layout.kind == PropertyLayout::kRestOfNode) break;
        if (layout.kind == PropertyLayout::kUnknown) return {};
        if (layout.kind == PropertyLayout::kValue) {
          p += 1 + layout.size;
          continue;
        }
        if (layout.kind == PropertyLayout::kSized) {
          if (p + 5 > properties_end) return {};
          p += 5 + read_le(bytes, p + 1, 4);
          continue;
        }
        if (p + 13 > properties_end) return {};
        const std::uint64_t count = read_le(bytes, p + 1, 4), encoding = read_le(bytes, p + 5, 4), stored = read_le(bytes, p + 9, 4);
        if (p + 13 + stored > properties_end) return {};
        if (layout.size > 0) {
          const std::uint64_t declared = count * layout.size;
          const std::string name(reinterpret_cast<const char*>(&bytes[at + null_record]), name_length);
          const std::string what = "its array '" + name + "' at byte " + std::to_string(p) + " declares " + std::to_string(count) + " values (" +
                                   format_bytes(static_cast<double>(declared)) + ")";
          if (declared > limit) return what + ", more than the memory available, " + format_bytes(static_cast<double>(limit));
          if (encoding == 1 && declared > stored * kInflateRatio + 64) {
            return what + " from " + std::to_string(stored) + " compressed bytes, more than zlib can inflate them to";
          }
          if (encoding == 1 && stored > 0 && !inflates(&bytes[p + 13], stored, static_cast<std::uint32_t>(declared), scratch)) {
            return what + " whose compressed bytes do not inflate";
          }
        }
        p += 13 + stored;
      }
      if (properties_end < node_end) {
        if (node_end - properties_end < null_record) return {};
        pending.push_back({properties_end, node_end - null_record, true});
      }
      at = node_end;
    }
  }
  return {};
}

}  // namespace atrium::assets
