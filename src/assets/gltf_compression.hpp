// Decoders for glTF's geometry compression: EXT_meshopt_compression
// bufferViews (Debian's libmeshoptimizer) and KHR_draco_mesh_compression
// primitives (Debian's libdraco). Both produce plain bytes laid out the way an
// uncompressed file would hold them, so accessors read them like any other.
#pragma once

#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "assets/gltf_document.hpp"

namespace atrium::assets::gltf {

// The meshopt stream of one compressed bufferView holds at most this many
// times its size once decoded (the vertex codec's best case: two header bits
// per 16 bytes); a view that claims more is refused before allocating.
inline constexpr std::size_t kMeshoptMaxExpansion = 64;

// The decoded bytes of `document.buffer_views[view]` (which has .meshopt set),
// filter applied. Throws ImportError naming the view.
[[nodiscard]] std::vector<std::uint8_t> decode_meshopt(const Document& document, std::size_t view, const MemoryBudget& budget);

// One accessor's elements as a Draco primitive decodes them: tightly packed,
// `count` of them (the decoded count, which may differ from the accessor's
// declared one), each component of `component_type`.
struct DecodedAccessor {
  std::vector<std::uint8_t> bytes;
  std::size_t count = 0;
  int component_type = 0;
};

struct DecodedDraco {
  std::map<int, DecodedAccessor> accessors;  // by accessor index
  // Where the decoded counts differ from the declared ones (encoders split
  // and merge vertices; files from public sample sets do this), one line each.
  std::vector<std::string> warnings;
};

// A Draco primitive decoded: its indices (as UNSIGNED_INT, whatever their
// accessor declares, since the decoded vertices may outnumber its type) and
// every attribute in the extension, in its accessor's componentType. Throws
// ImportError naming `where` for what cannot be drawn.
[[nodiscard]] DecodedDraco decode_draco(const Document& document, const Primitive& primitive, std::span<const std::uint8_t> stream,
                                        const std::string& where, const MemoryBudget& budget);

}  // namespace atrium::assets::gltf
