// The glTF decoders for the WebAssembly build, which has neither
// libmeshoptimizer nor libdraco: a compressed file is refused with one line
// naming the way out (the native build decodes both, assets/gltf_compression.cpp).
#include "assets/gltf_compression.hpp"

namespace atrium::assets::gltf {

std::vector<std::uint8_t> decode_meshopt(const Document& document, std::size_t view, const MemoryBudget&) {
  throw ImportError(document.path.string() + ": /bufferViews/" + std::to_string(view) +
                    ": EXT_meshopt_compression needs libmeshoptimizer, which the browser build does not have; "
                    "decompress the file first (`gltfpack -i in.glb -o out.glb -noq`)");
}

DecodedDraco decode_draco(const Document& document, const Primitive&, std::span<const std::uint8_t>, const std::string& where,
                          const MemoryBudget&) {
  throw ImportError(document.path.string() + ": " + where +
                    ": KHR_draco_mesh_compression needs libdraco, which the browser build does not have; decompress the "
                    "file first (`gltf-transform copy in.glb out.glb`)");
}

}  // namespace atrium::assets::gltf
