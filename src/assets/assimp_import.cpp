#include "assets/assimp_import.hpp"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <iterator>
#include <map>

#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "assets/assimp_file_access.hpp"
#include "assets/file_lookup.hpp"
#include "assets/texture_decode.hpp"

namespace atrium::assets {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::string first_line(std::string text) {
  text = text.substr(0, text.find('\n'));
  while (!text.empty() && (text.back() == '\r' || text.back() == ' ')) text.pop_back();
  return text.empty() ? "not a model file Atrium can read" : text;
}

glm::mat4 to_glm(const aiMatrix4x4& m) { return glm::transpose(glm::make_mat4(&m.a1)); }

// The metadata value `key` as a double, whatever numeric type the file stored.
std::optional<double> metadata_number(const aiMetadata* metadata, const char* key) {
  if (!metadata) return std::nullopt;
  for (unsigned i = 0; i < metadata->mNumProperties; ++i) {
    if (std::string(metadata->mKeys[i].C_Str()) != key) continue;
    const aiMetadataEntry& entry = metadata->mValues[i];
    switch (entry.mType) {
      case AI_INT32: return *static_cast<const std::int32_t*>(entry.mData);
      case AI_UINT64: return static_cast<double>(*static_cast<const std::uint64_t*>(entry.mData));
      case AI_FLOAT: return *static_cast<const float*>(entry.mData);
      case AI_DOUBLE: return *static_cast<const double*>(entry.mData);
      default: return std::nullopt;
    }
  }
  return std::nullopt;
}

// FBX files say their units (UnitScaleFactor: centimetres per unit) and axes
// (which file axis is up, forward and right, with signs); the transform that
// takes such a file to metres, +Y up, +Z forward. Other formats: identity.
glm::mat4 file_to_world(const aiScene& scene) {
  const aiMetadata* m = scene.mMetaData;
  const double centimetres = metadata_number(m, "UnitScaleFactor").value_or(100.0);
  glm::mat4 basis(1.0f);
  const auto up = metadata_number(m, "UpAxis"), front = metadata_number(m, "FrontAxis"), coord = metadata_number(m, "CoordAxis");
  if (up && front && coord && *up != *front && *up != *coord && *front != *coord && *up >= 0 && *up <= 2 && *front >= 0 && *front <= 2 &&
      *coord >= 0 && *coord <= 2) {
    auto axis = [&](double index, const char* sign_key) {
      glm::vec3 v(0.0f);
      v[static_cast<int>(index)] = metadata_number(m, sign_key).value_or(1.0) < 0.0 ? -1.0f : 1.0f;
      return v;
    };
    // Columns: where Atrium's right, up and forward lie in the file.
    const glm::mat3 file_axes(axis(*coord, "CoordAxisSign"), axis(*up, "UpAxisSign"), axis(*front, "FrontAxisSign"));
    basis = glm::mat4(glm::transpose(file_axes));
  }
  return glm::scale(glm::mat4(1.0f), glm::vec3(static_cast<float>(centimetres / 100.0))) * basis;
}

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

class AssimpImporter {
 public:
  AssimpImporter(const fs::path& path, AssetManager& assets, const ImportOptions& options)
      : path_(path), name_(path.string()), assets_(assets), options_(options), budget_(options.memory_limit) {
    budget_.set_file(name_);
    const std::string extension = lower(path.extension().string());
    convention_ = options.convention.value_or(extension == ".obj" ? MaterialConvention::Phong : MaterialConvention::Gltf);
  }

  ModelImport run() {
    const auto start = Clock::now();
    std::error_code ec;
    if (!fs::is_regular_file(path_, ec)) fail("no such file");
    Assimp::Importer importer;
    // Owned by the importer, which outlives every use of it here.
    auto* files = new AssimpFileAccess(path_, budget_.limit());
    importer.SetIOHandler(files);
    // Points and lines are dropped; everything else becomes triangle lists.
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    const unsigned flags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_SortByPType | aiProcess_GenSmoothNormals |
                           aiProcess_FlipUVs | aiProcess_ValidateDataStructure;
    const aiScene* scene = importer.ReadFile(path_.string(), flags);
    for (const AssimpFileAccess::Access& access : files->accesses()) {
      if (fs::path(access.asked) == path_ && !access.problem.empty()) fail(access.problem);
    }
    for (std::string& line : files->warnings()) warn(std::move(line));
    if (!scene || !scene->mRootNode) fail(first_line(importer.GetErrorString()));
    if (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) fail("the file is incomplete (" + first_line(importer.GetErrorString()) + ")");
    scene_ = scene;
    MeshAsset asset;
    asset.name = path_.filename().string();
    read_materials(asset);
    read_meshes(asset);
    if (non_finite_ > 0) {
      warn(std::to_string(non_finite_) + " of " + std::to_string(triangles_read_) + " triangles have a NaN or infinite corner; they are skipped");
    }
    if (zero_area_ > 0) {
      warn(std::to_string(zero_area_) + " of " + std::to_string(triangles_read_) + " triangles have zero area; they are skipped");
    }
    result_.timings.parse_seconds = seconds_since(start);
    const auto decode_start = Clock::now();
    decode_textures(asset.materials);
    result_.timings.decode_seconds = seconds_since(decode_start);
    place_nodes(asset, *scene->mRootNode, file_to_world(*scene));
    if (scene->mNumLights > 0) {
      warn(std::to_string(scene->mNumLights) + " lights in the file are not imported (their intensities have no common unit); "
           "a scene file adds lights");
    }
    result_.asset = assets_.add_mesh_asset(std::move(asset), fs::weakly_canonical(path_).string());
    return std::move(result_);
  }

 private:
  [[noreturn]] void fail(const std::string& problem) const { throw ImportError(name_ + ": " + problem); }
  void warn(const std::string& problem) { result_.warnings.push_back(name_ + ": " + problem); }

  // --- meshes ----------------------------------------------------------------

  void read_meshes(MeshAsset& asset) {
    for (unsigned m = 0; m < scene_->mNumMeshes; ++m) {
      const aiMesh& source = *scene_->mMeshes[m];
      const std::string what = "mesh " + std::to_string(m) + (source.mName.length ? " '" + std::string(source.mName.C_Str()) + "'" : "");
      Mesh mesh;
      mesh.name = source.mName.length ? source.mName.C_Str() : "mesh " + std::to_string(m);
      if (!(source.mPrimitiveTypes & aiPrimitiveType_TRIANGLE) || source.mNumFaces == 0) {
        asset.meshes.push_back(std::move(mesh));  // keeps node mesh indices valid
        continue;
      }
      Geometry geometry;
      geometry.vertices.resize(budget_.bytes(source.mNumVertices, sizeof(Vertex), what) / sizeof(Vertex));
      for (unsigned i = 0; i < source.mNumVertices; ++i) {
        Vertex& v = geometry.vertices[i];
        v.position = {source.mVertices[i].x, source.mVertices[i].y, source.mVertices[i].z};
        if (source.mNormals) v.normal = {source.mNormals[i].x, source.mNormals[i].y, source.mNormals[i].z};
        if (source.mTextureCoords[0]) v.uv0 = {source.mTextureCoords[0][i].x, source.mTextureCoords[0][i].y};
        if (source.mTextureCoords[1]) v.uv1 = {source.mTextureCoords[1][i].x, source.mTextureCoords[1][i].y};
        if (source.mColors[0]) {
          const aiColor4D& c = source.mColors[0][i];
          const float channels[4] = {c.r, c.g, c.b, c.a};
          for (int k = 0; k < 4; ++k) v.color[static_cast<std::size_t>(k)] = static_cast<std::uint16_t>(std::lround(std::clamp(channels[k], 0.0f, 1.0f) * 65535.0f));
        }
      }
      geometry.indices.reserve(budget_.bytes(static_cast<std::size_t>(source.mNumFaces) * 3, sizeof(std::uint32_t), what) / sizeof(std::uint32_t));
      for (unsigned f = 0; f < source.mNumFaces; ++f) {
        const aiFace& face = source.mFaces[f];
        if (face.mNumIndices != 3) continue;
        for (int k = 0; k < 3; ++k) {
          if (face.mIndices[k] >= source.mNumVertices) fail(what + ": face " + std::to_string(f) + " has an index past its vertices");
          geometry.indices.push_back(face.mIndices[k]);
        }
      }
      triangles_read_ += geometry.indices.size() / 3;
      const DroppedTriangles dropped = drop_unusable_triangles(geometry.vertices, geometry.indices);
      non_finite_ += dropped.non_finite;
      zero_area_ += dropped.zero_area;
      if (!source.mNormals) generate_normals(geometry);
      if (repair_normals(geometry.vertices, geometry.indices)) warn(what + " has zero-length or invalid normals; they were regenerated");
      generate_tangents(geometry);
      const std::uint32_t material = source.mMaterialIndex < asset.materials.size() ? source.mMaterialIndex : default_material(asset);
      mesh.primitives.push_back(add_geometry(asset, std::move(geometry), material));
      asset.meshes.push_back(std::move(mesh));
    }
  }

  std::uint32_t default_material(MeshAsset& asset) {
    if (!default_material_) {
      Material m;
      m.name = "default";
      m.metallic_factor = 0.0f;
      asset.materials.push_back(m);
      default_material_ = static_cast<std::uint32_t>(asset.materials.size() - 1);
    }
    return *default_material_;
  }

  // --- nodes -----------------------------------------------------------------

  void place_nodes(const MeshAsset& asset, const aiNode& root, const glm::mat4& file_to_world) {
    Box bounds;
    std::size_t skipped = 0;
    std::vector<std::pair<const aiNode*, glm::mat4>> stack{{&root, file_to_world}};
    while (!stack.empty()) {
      const auto [node, parent] = stack.back();
      stack.pop_back();
      const glm::mat4 world = parent * to_glm(node->mTransformation);
      for (unsigned i = 0; i < node->mNumMeshes; ++i) {
        const unsigned mesh = node->mMeshes[i];
        if (mesh >= asset.meshes.size() || asset.meshes[mesh].primitives.empty()) continue;
        const std::optional<Transform> transform = from_matrix(world);
        if (!transform) {
          ++skipped;
          continue;
        }
        result_.instances.push_back({MeshAssetHandle{}, mesh, *transform});
        for (const Primitive& p : asset.meshes[mesh].primitives) {
          if (!p.indices.empty()) bounds.add_box(world, p.bounds_min, p.bounds_max);
        }
      }
      for (unsigned c = 0; c < node->mNumChildren; ++c) stack.emplace_back(node->mChildren[c], world);
    }
    if (skipped > 0) warn(std::to_string(skipped) + " instances have a transform with a zero or non-finite scale; they are skipped");
    result_.bounds = bounds;
  }

  // --- materials and textures ----------------------------------------------

  // A texture a material asks for, before it is found and decoded.
  struct Wanted {
    std::size_t material;
    enum class Role { BaseColor, MetallicRoughness, Normal, Occlusion, Emissive, Opacity } role;
    std::string path;  // as the file wrote it
    ColorSpace space;
  };

  std::optional<std::string> texture_path(const aiMaterial& m, std::initializer_list<aiTextureType> types) {
    for (const aiTextureType type : types) {
      aiString path;
      if (m.GetTextureCount(type) > 0 && m.GetTexture(type, 0, &path) == AI_SUCCESS && path.length > 0) return std::string(path.C_Str());
    }
    return std::nullopt;
  }

  void read_materials(MeshAsset& asset) {
    for (unsigned i = 0; i < scene_->mNumMaterials; ++i) {
      const aiMaterial& src = *scene_->mMaterials[i];
      Material m;
      aiString name;
      m.name = src.Get(AI_MATKEY_NAME, name) == AI_SUCCESS && name.length ? name.C_Str() : "material " + std::to_string(i);
      int two_sided = 0;
      if (src.Get(AI_MATKEY_TWOSIDED, two_sided) == AI_SUCCESS) m.double_sided = two_sided != 0;
      aiColor4D base(1.0f, 1.0f, 1.0f, 1.0f);
      aiColor3D diffuse(1.0f, 1.0f, 1.0f), emissive(0.0f, 0.0f, 0.0f);
      float opacity = 1.0f, shininess = 0.0f, metallic = 0.0f, roughness = 0.5f;
      const bool has_base = src.Get(AI_MATKEY_BASE_COLOR, base) == AI_SUCCESS;
      if (!has_base && src.Get(AI_MATKEY_COLOR_DIFFUSE, diffuse) == AI_SUCCESS) base = aiColor4D(diffuse.r, diffuse.g, diffuse.b, 1.0f);
      src.Get(AI_MATKEY_OPACITY, opacity);
      src.Get(AI_MATKEY_COLOR_EMISSIVE, emissive);
      const bool has_shininess = src.Get(AI_MATKEY_SHININESS, shininess) == AI_SUCCESS && shininess > 0.0f;
      const bool has_metallic = src.Get(AI_MATKEY_METALLIC_FACTOR, metallic) == AI_SUCCESS;
      const bool has_roughness = src.Get(AI_MATKEY_ROUGHNESS_FACTOR, roughness) == AI_SUCCESS;
      // A Blinn-Phong exponent as GGX roughness: the lobes agree where
      // roughness = sqrt(2 / (exponent + 2)).
      if (!has_roughness && has_shininess) roughness = std::sqrt(2.0f / (shininess + 2.0f));
      m.base_color_factor = glm::vec4(base.r, base.g, base.b, std::clamp(opacity, 0.0f, 1.0f) * base.a);
      // Bistro's factors are 1 where its "Specular" texture carries the values.
      const bool bistro_packed = convention_ == MaterialConvention::Bistro && texture_path(src, {aiTextureType_SPECULAR});
      m.metallic_factor = bistro_packed ? 1.0f : has_metallic ? metallic : 0.0f;
      m.roughness_factor = bistro_packed ? 1.0f : std::clamp(roughness, 0.0f, 1.0f);
      m.emissive_factor = glm::vec3(emissive.r, emissive.g, emissive.b);
      if (m.base_color_factor.a < 0.999f) m.alpha_mode = AlphaMode::Blend;
      m.normal_green_down = convention_ == MaterialConvention::Bistro;

      const std::size_t index = asset.materials.size();
      auto want = [&](Wanted::Role role, std::optional<std::string> path, ColorSpace space) {
        if (path) wanted_.push_back({index, role, *path, space});
      };
      want(Wanted::Role::BaseColor, texture_path(src, {aiTextureType_BASE_COLOR, aiTextureType_DIFFUSE}), ColorSpace::Srgb);
      want(Wanted::Role::Normal, texture_path(src, {aiTextureType_NORMALS, aiTextureType_NORMAL_CAMERA, aiTextureType_HEIGHT}),
           ColorSpace::Linear);
      const auto emissive_texture = texture_path(src, {aiTextureType_EMISSION_COLOR, aiTextureType_EMISSIVE});
      want(Wanted::Role::Emissive, emissive_texture, ColorSpace::Srgb);
      if (emissive_texture && m.emissive_factor == glm::vec3(0.0f)) m.emissive_factor = glm::vec3(1.0f);
      if (convention_ == MaterialConvention::Bistro) {
        // "Specular": occlusion in red, roughness in green, metalness in blue.
        want(Wanted::Role::MetallicRoughness, texture_path(src, {aiTextureType_SPECULAR}), ColorSpace::Linear);
        want(Wanted::Role::Occlusion, texture_path(src, {aiTextureType_SPECULAR}), ColorSpace::Linear);
      } else if (convention_ == MaterialConvention::Gltf) {
        const auto metal = texture_path(src, {aiTextureType_METALNESS}), rough = texture_path(src, {aiTextureType_DIFFUSE_ROUGHNESS});
        if (metal && rough && *metal == *rough) {
          want(Wanted::Role::MetallicRoughness, metal, ColorSpace::Linear);
          m.metallic_factor = has_metallic ? metallic : 1.0f;
          m.roughness_factor = has_roughness ? roughness : 1.0f;
        } else if (metal || rough) {
          warn("materials[" + std::to_string(i) + "] '" + m.name + "' has separate metalness and roughness textures; Atrium reads one "
               "packed texture, so its factors are used");
        }
        want(Wanted::Role::Occlusion, texture_path(src, {aiTextureType_AMBIENT_OCCLUSION, aiTextureType_LIGHTMAP}), ColorSpace::Linear);
      } else {
        want(Wanted::Role::Opacity, texture_path(src, {aiTextureType_OPACITY}), ColorSpace::Linear);
      }
      asset.materials.push_back(m);
    }
  }

  // The file a texture path names (file_lookup.hpp), with a warning when it
  // was not where the path says.
  std::optional<fs::path> find_texture(const std::string& written) {
    if (const auto known = found_.find(written); known != found_.end()) return known->second;
    const FoundFile found = find_named_file(path_.parent_path(), written);
    if (found.path && !found.how.empty()) {
      std::error_code ec;
      warn("texture '" + written + "' " + found.how + "; " + fs::relative(*found.path, path_.parent_path(), ec).generic_string() + " is used");
    }
    found_[written] = found.path;
    return found.path;
  }

  // Whether the model holds the texture it names: "*3", or (FBX) a file name
  // whose bytes it embeds.
  bool embedded(const std::string& written) const { return written[0] == '*' || scene_->GetEmbeddedTexture(written.c_str()); }

  // Reads a texture's bytes: a file, or one the file embeds.
  std::vector<std::uint8_t> texture_bytes(const std::string& written, const fs::path* file, std::string& error) {
    if (embedded(written)) {
      const aiTexture* embedded = scene_->GetEmbeddedTexture(written.c_str());
      if (!embedded) {
        error = "no embedded texture " + written;
        return {};
      }
      if (embedded->mHeight == 0) {
        const auto* data = reinterpret_cast<const std::uint8_t*>(embedded->pcData);
        return std::vector<std::uint8_t>(data, data + embedded->mWidth);
      }
      error = "an uncompressed embedded texture, which Atrium does not read";
      return {};
    }
    if (!file) {
      error = "the file is missing";
      return {};
    }
    FileBytes read = read_file_within(*file, budget_.limit());
    error = std::move(read.problem);
    return std::move(read.bytes);
  }

  void decode_textures(std::vector<Material>& materials) {
    // One decode per (file, colour space).
    std::map<std::pair<std::string, ColorSpace>, std::size_t> job_of;
    struct Job {
      std::string written;
      std::optional<fs::path> file;
      ColorSpace space;
    };
    std::vector<Job> jobs;
    std::vector<std::size_t> job_of_wanted;
    for (const Wanted& w : wanted_) {
      std::optional<fs::path> file;
      if (!embedded(w.path)) file = find_texture(w.path);
      const std::string key = file ? fs::weakly_canonical(*file).string() : w.path;
      const auto [it, added] = job_of.try_emplace({key, w.space}, jobs.size());
      if (added) jobs.push_back({w.path, file, w.space});
      job_of_wanted.push_back(it->second);
    }
    std::vector<DecodedTexture> decoded = decode_in_parallel(
        jobs.size(),
        [&](std::size_t j) {
          DecodedTexture result;
          const std::vector<std::uint8_t> bytes = texture_bytes(jobs[j].written, jobs[j].file ? &*jobs[j].file : nullptr, result.error);
          return result.error.empty() ? decode_texture(bytes, jobs[j].space, budget_.limit()) : result;
        },
        options_.decode_threads, options_.progress);
    const std::string canonical = fs::weakly_canonical(path_).string();
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
      Material& m = materials[wanted.material];
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
  void apply_opacity(Material& m, const std::string& what, const TextureData& opacity, const std::string& name) {
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

  fs::path path_;
  std::string name_;
  AssetManager& assets_;
  const ImportOptions& options_;
  MemoryBudget budget_;
  MaterialConvention convention_;
  const aiScene* scene_ = nullptr;
  std::vector<Wanted> wanted_;
  std::map<std::string, std::optional<fs::path>> found_;
  std::optional<std::uint32_t> default_material_;
  std::size_t triangles_read_ = 0, non_finite_ = 0, zero_area_ = 0;
  ModelImport result_;
};

}  // namespace

ModelImport import_assimp(const std::filesystem::path& path, AssetManager& assets, const ImportOptions& options) {
  return refuse_out_of_memory(path, [&] { return AssimpImporter(path, assets, options).run(); });
}

}  // namespace atrium::assets
