#include "assets/gltf_extensions.hpp"

#include <algorithm>
#include <array>

namespace atrium::assets {
namespace {

constexpr std::array kExtensions{
    GltfExtension{"KHR_draco_mesh_compression", true, "decoded with Debian's libdraco"},
    GltfExtension{"EXT_meshopt_compression", true, "decoded with Debian's libmeshoptimizer, every mode and filter; fallback buffers without data load"},
    GltfExtension{"KHR_mesh_quantization", true, "integer and normalised attributes are read"},
    GltfExtension{"EXT_mesh_gpu_instancing", true, "each instance becomes an entity; identical meshes are drawn instanced"},
    GltfExtension{"KHR_lights_punctual", true, "point, spot and directional lights become light entities"},
    GltfExtension{"KHR_materials_emissive_strength", true, "scales the emission"},
    GltfExtension{"KHR_materials_unlit", true, "the base colour is drawn as is, in every mode and shading model"},
    GltfExtension{"KHR_texture_transform", true, "offset, rotation, scale and texCoord per texture"},
    GltfExtension{"MSFT_texture_dds", true, "DDS images (BC1-BC5, BC7, uncompressed) are preferred and uploaded still compressed"},
    GltfExtension{"KHR_xmp_json_ld", true, "metadata; nothing to draw"},
    GltfExtension{"KHR_xmp", true, "metadata; nothing to draw"},
    GltfExtension{"KHR_materials_clearcoat", false, "the clear-coat layer is not drawn"},
    GltfExtension{"KHR_materials_transmission", false, "transmissive surfaces are drawn opaque (or with their alpha)"},
    GltfExtension{"KHR_materials_volume", false, "thickness and attenuation inside volumes are lost"},
    GltfExtension{"KHR_materials_ior", false, "the index of refraction is taken as 1.5"},
    GltfExtension{"KHR_materials_specular", false, "specular strength and colour are lost (dielectrics reflect 4%)"},
    GltfExtension{"KHR_materials_sheen", false, "the sheen layer is not drawn"},
    GltfExtension{"KHR_materials_iridescence", false, "iridescence is not drawn"},
    GltfExtension{"KHR_materials_anisotropy", false, "highlights are drawn isotropic"},
    GltfExtension{"KHR_materials_dispersion", false, "dispersion is not drawn"},
    GltfExtension{"KHR_materials_diffuse_transmission", false, "light through thin surfaces is not drawn"},
    GltfExtension{"KHR_materials_variants", false, "only each primitive's default material is drawn"},
    GltfExtension{"KHR_materials_pbrSpecularGlossiness", false, "specular-glossiness materials draw with their metallic-roughness values"},
    GltfExtension{"KHR_texture_basisu", false, "KTX2 textures are not read; a texture's PNG or JPEG source is used where it has one"},
    GltfExtension{"EXT_texture_webp", false, "WebP images are not read; a texture's PNG or JPEG source is used where it has one"},
    GltfExtension{"EXT_texture_avif", false, "AVIF images are not read; a texture's PNG or JPEG source is used where it has one"},
    GltfExtension{"KHR_meshopt_compression", false, "its compressed geometry cannot be read; fallback data is used where the file has it"},
    GltfExtension{"KHR_animation_pointer", false, "animations are not played (Atrium plays none)"},
    GltfExtension{"KHR_node_visibility", false, "hidden nodes are drawn"},
    GltfExtension{"EXT_lights_image_based", false, "image-based lighting is lost"},
    GltfExtension{"EXT_lights_ies", false, "IES light profiles are lost (the lights shine evenly)"},
    GltfExtension{"MSFT_lod", false, "only the most detailed level is drawn"},
};

}  // namespace

std::span<const GltfExtension> gltf_extensions() { return kExtensions; }

const GltfExtension* find_gltf_extension(std::string_view name) {
  const auto it = std::find_if(kExtensions.begin(), kExtensions.end(), [&](const GltfExtension& e) { return e.name == name; });
  return it == kExtensions.end() ? nullptr : &*it;
}

}  // namespace atrium::assets
