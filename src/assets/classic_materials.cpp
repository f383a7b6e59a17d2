#include "assets/classic_materials.hpp"

#include <algorithm>
#include <cmath>

#include "assets/file_lookup.hpp"
#include "assets/load_budget.hpp"
#include "assets/texture_decode.hpp"

namespace atrium::assets {
namespace {

namespace fs = std::filesystem;

// Whether a texture has texels that an alpha mask would cut (alpha below half).
bool has_transparent_texels(const TextureData& texture) {
  if (!texture.compressed) {
    for (std::size_t i = 3; i < texture.image.rgba.size(); i += 4) {
      if (texture.image.rgba[i] < 128) return true;
    }
    return false;
  }
  const CompressedImage& c = *texture.compressed;
  const std::vector<std::uint8_t>& blocks = c.levels.at(0);
  const std::size_t size = block_bytes(c.format);
  for (std::size_t b = 0; b + size <= blocks.size(); b += size) {
    const std::uint8_t* block = &blocks[b];
    switch (c.format) {
      case BlockFormat::BC1: {
        // Three-colour mode (colour 0 <= colour 1) has a transparent index 3.
        const std::uint16_t c0 = static_cast<std::uint16_t>(block[0] | block[1] << 8), c1 = static_cast<std::uint16_t>(block[2] | block[3] << 8);
        if (c0 > c1) break;
        for (int i = 4; i < 8; ++i) {
          for (int k = 0; k < 8; k += 2) {
            if (((block[i] >> k) & 3) == 3) return true;
          }
        }
        break;
      }
      case BlockFormat::BC2:
        for (int i = 0; i < 8; ++i) {
          if ((block[i] & 0x0f) < 8 || (block[i] >> 4) < 8) return true;
        }
        break;
      case BlockFormat::BC3:
        if (std::min(block[0], block[1]) < 128) return true;
        break;
      default: break;  // BC4 and BC5 hold data; BC7 is read as opaque
    }
  }
  return false;
}

// A greyscale image (every texel's red, green and blue equal): a height map in
// a bump slot, not a normal map.
bool greyscale(const TextureData& texture) {
  if (texture.compressed) return texture.compressed->format == BlockFormat::BC4;
  const auto& rgba = texture.image.rgba;
  for (std::size_t i = 0; i + 3 < rgba.size(); i += 4 * 97) {
    if (rgba[i] != rgba[i + 1] || rgba[i] != rgba[i + 2]) return false;
  }
  return !rgba.empty();
}

}  // namespace

ClassicMaterials::ClassicMaterials(const fs::path& model, MaterialConvention convention, AssetManager& assets, const ImportOptions& options,
                                   ModelImport& result)
    : model_(model), name_(model.string()), convention_(convention), assets_(assets), options_(options), result_(result) {}

void ClassicMaterials::warn(const std::string& problem) { result_.warnings.push_back(name_ + ": " + problem); }

Material ClassicMaterials::convert(const ClassicMaterial& src, std::size_t index) {
  Material m;
  m.name = src.name.empty() ? "material " + std::to_string(index) : src.name;
  if (src.two_sided) m.double_sided = *src.two_sided;
  const glm::vec4 base = src.base_color.value_or(glm::vec4(src.diffuse, 1.0f));
  float roughness = src.roughness.value_or(0.5f);
  // A Blinn-Phong exponent as GGX roughness: the lobes agree where
  // roughness = sqrt(2 / (exponent + 2)).
  if (!src.roughness && src.shininess && *src.shininess > 0.0f) roughness = std::sqrt(2.0f / (*src.shininess + 2.0f));
  m.base_color_factor = glm::vec4(glm::vec3(base), std::clamp(src.opacity, 0.0f, 1.0f) * base.a);
  // Bistro's factors are 1 where its "Specular" texture carries the values.
  const bool bistro_packed = convention_ == MaterialConvention::Bistro && src.specular_texture;
  m.metallic_factor = bistro_packed ? 1.0f : src.metallic.value_or(0.0f);
  m.roughness_factor = bistro_packed ? 1.0f : std::clamp(roughness, 0.0f, 1.0f);
  m.emissive_factor = src.emissive;
  if (m.base_color_factor.a < 0.999f) m.alpha_mode = AlphaMode::Blend;
  m.normal_green_down = convention_ == MaterialConvention::Bistro;

  auto want = [&](Wanted::Role role, const std::optional<std::string>& path, ColorSpace space) {
    if (path) wanted_.push_back({index, role, *path, space});
  };
  want(Wanted::Role::BaseColor, src.base_color_texture, ColorSpace::Srgb);
  want(Wanted::Role::Normal, src.normal_texture, ColorSpace::Linear);
  want(Wanted::Role::Emissive, src.emissive_texture, ColorSpace::Srgb);
  if (src.emissive_texture && m.emissive_factor == glm::vec3(0.0f)) m.emissive_factor = glm::vec3(1.0f);
  if (convention_ == MaterialConvention::Bistro) {
    // "Specular": occlusion in red, roughness in green, metalness in blue.
    want(Wanted::Role::MetallicRoughness, src.specular_texture, ColorSpace::Linear);
    want(Wanted::Role::Occlusion, src.specular_texture, ColorSpace::Linear);
  } else if (convention_ == MaterialConvention::Gltf) {
    const auto& metal = src.metalness_texture;
    const auto& rough = src.roughness_texture;
    if (metal && rough && *metal == *rough) {
      want(Wanted::Role::MetallicRoughness, metal, ColorSpace::Linear);
      m.metallic_factor = src.metallic.value_or(1.0f);
      m.roughness_factor = src.roughness.value_or(1.0f);
    } else if (metal || rough) {
      warn("materials[" + std::to_string(index) + "] '" + m.name + "' has separate metalness and roughness textures; Atrium reads one "
           "packed texture, so its factors are used");
    }
    want(Wanted::Role::Occlusion, src.occlusion_texture, ColorSpace::Linear);
  } else {
    want(Wanted::Role::Opacity, src.opacity_texture, ColorSpace::Linear);
  }
  return m;
}

std::uint32_t ClassicMaterials::default_material(MeshAsset& asset) {
  if (!default_material_) {
    Material m;
    m.name = "default";
    m.metallic_factor = 0.0f;
    asset.materials.push_back(m);
    default_material_ = static_cast<std::uint32_t>(asset.materials.size() - 1);
  }
  return *default_material_;
}

// The file a texture path names (file_lookup.hpp), with a warning when it
// was not where the path says.
std::optional<fs::path> ClassicMaterials::find_texture(const std::string& written) {
  if (const auto known = found_.find(written); known != found_.end()) return known->second;
  const FoundFile found = find_named_file(model_.parent_path(), written);
  if (found.path && !found.how.empty()) warn("texture " + found_elsewhere_warning(written, found.how, *found.path, model_.parent_path()));
  found_[written] = found.path;
  return found.path;
}

void ClassicMaterials::decode(std::vector<Material>& materials, const EmbeddedTextures& embedded) {
  const std::size_t limit = MemoryBudget(options_.memory_limit).limit();
  // One decode per (file or embedded texture, colour space).
  struct Job {
    std::string written;
    std::optional<fs::path> file;
    bool embedded = false;
    ColorSpace space;
  };
  std::map<std::pair<std::string, ColorSpace>, std::size_t> job_of;
  std::vector<Job> jobs;
  std::vector<std::size_t> job_of_wanted;
  for (const Wanted& w : wanted_) {
    const bool inside = embedded.holds && embedded.holds(w.path);
    std::optional<fs::path> file;
    if (!inside) file = find_texture(w.path);
    const std::string key = file ? fs::weakly_canonical(*file).string() : w.path;
    const auto [it, added] = job_of.try_emplace({key, w.space}, jobs.size());
    if (added) jobs.push_back({w.path, file, inside, w.space});
    job_of_wanted.push_back(it->second);
  }
  std::vector<DecodedTexture> decoded = decode_in_parallel(
      jobs.size(),
      [&](std::size_t j) {
        DecodedTexture result;
        std::vector<std::uint8_t> bytes;
        if (jobs[j].embedded) {
          bytes = embedded.read(jobs[j].written, result.error);
        } else if (!jobs[j].file) {
          result.error = "the file is missing";
        } else {
          FileBytes read = read_file_within(*jobs[j].file, limit);
          result.error = std::move(read.problem);
          bytes = std::move(read.bytes);
        }
        return result.error.empty() ? decode_texture(bytes, jobs[j].space, limit) : result;
      },
      options_.decode_threads, options_.progress);
  const std::string canonical = fs::weakly_canonical(model_).string();
  std::vector<TextureHandle> handles(jobs.size());
  for (std::size_t j = 0; j < jobs.size(); ++j) {
    if (!decoded[j].texture) {
      warn("texture '" + jobs[j].written + "' cannot be decoded (" + decoded[j].error + "); a neutral default texture is used");
      continue;
    }
    decoded[j].texture->name = jobs[j].written;
    const std::string key = canonical + "#" + (jobs[j].file ? jobs[j].file->string() : jobs[j].written) +
                            (jobs[j].space == ColorSpace::Srgb ? "/srgb" : "/linear");
    handles[j] = assets_.add_texture(std::move(*decoded[j].texture), key);
    ++result_.images;
  }
  for (std::size_t w = 0; w < wanted_.size(); ++w) {
    const Wanted& wanted = wanted_[w];
    const std::size_t j = job_of_wanted[w];
    if (!handles[j].valid()) continue;
    Material& m = materials.at(wanted.material);
    const TextureData& texture = assets_.texture(handles[j]);
    const std::string what = "materials[" + std::to_string(wanted.material) + "] '" + m.name + "'";
    switch (wanted.role) {
      case Wanted::Role::BaseColor:
        m.base_color_texture.texture = handles[j];
        if (m.alpha_mode == AlphaMode::Opaque && has_transparent_texels(texture)) m.alpha_mode = AlphaMode::Mask;
        break;
      case Wanted::Role::MetallicRoughness: m.metallic_roughness_texture.texture = handles[j]; break;
      case Wanted::Role::Occlusion: m.occlusion_texture.texture = handles[j]; break;
      case Wanted::Role::Emissive: m.emissive_texture.texture = handles[j]; break;
      case Wanted::Role::Normal:
        if (greyscale(texture)) {
          warn(what + ": its bump texture '" + wanted.path + "' is a height map (greyscale); height maps are not drawn");
        } else {
          m.normal_texture.texture = handles[j];
        }
        break;
      case Wanted::Role::Opacity: apply_opacity(m, what, TextureData(texture), wanted.path); break;
    }
  }
}

// An OBJ opacity map (map_d) becomes the base colour texture's alpha, and the
// material alpha-masked.
void ClassicMaterials::apply_opacity(Material& m, const std::string& what, const TextureData& opacity, const std::string& name) {
  const TextureData* base = m.base_color_texture.valid() ? &assets_.texture(m.base_color_texture.texture) : nullptr;
  if (opacity.compressed || (base && base->compressed) ||
      (base && (base->image.width != opacity.image.width || base->image.height != opacity.image.height))) {
    warn(what + ": its opacity texture '" + name + "' does not match its colour texture in size or format; it is not used");
    return;
  }
  TextureData merged;
  merged.name = (base ? base->name + " with " : std::string()) + "opacity " + name;
  merged.color_space = ColorSpace::Srgb;
  merged.image = base ? base->image : Image{opacity.image.width, opacity.image.height, std::vector<std::uint8_t>(opacity.image.rgba.size(), 255)};
  for (std::size_t i = 0; i + 3 < merged.image.rgba.size(); i += 4) merged.image.rgba[i + 3] = opacity.image.rgba[i];
  m.base_color_texture.texture = assets_.add_texture(std::move(merged));
  m.alpha_mode = AlphaMode::Mask;
  m.alpha_cutoff = 0.5f;
}

}  // namespace atrium::assets
