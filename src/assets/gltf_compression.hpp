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

// A Draco primitive decoded into one tightly packed byte array per accessor
// it names (its indices and every attribute in the extension), each in that
// accessor's declared componentType. Throws ImportError naming `where`.
[[nodiscard]] std::map<int, std::vector<std::uint8_t>> decode_draco(const Document& document, const Primitive& primitive,
                                                                    std::span<const std::uint8_t> stream, const std::string& where,
                                                                    const MemoryBudget& budget);

}  // namespace atrium::assets::gltf
