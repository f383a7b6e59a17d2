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
#include "assets/classic_materials.hpp"

namespace atrium::assets {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

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

class AssimpImporter {
 public:
  AssimpImporter(const fs::path& path, AssetManager& assets, const ImportOptions& options)
      : path_(path),
        name_(path.string()),
        assets_(assets),
        budget_(options.memory_limit),
        materials_(path, options.convention.value_or(MaterialConvention::Gltf), assets, options, result_) {
    budget_.set_file(name_);
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
    for (const std::string& line : dropped_triangle_lines(dropped_, triangles_read_)) warn(line);
    result_.timings.parse_seconds = seconds_since(start);
    const auto decode_start = Clock::now();
    materials_.decode(asset.materials, embedded_textures());
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
      dropped_ += drop_unusable_triangles(geometry.vertices, geometry.indices);
      if (!source.mNormals) generate_normals(geometry);
      if (repair_normals(geometry.vertices, geometry.indices)) warn(what + " has zero-length or invalid normals; they were regenerated");
      generate_tangents(geometry);
      const std::uint32_t material = source.mMaterialIndex < asset.materials.size() ? source.mMaterialIndex : materials_.default_material(asset);
      mesh.primitives.push_back(add_geometry(asset, std::move(geometry), material));
      asset.meshes.push_back(std::move(mesh));
    }
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
      ClassicMaterial m;
      aiString name;
      if (src.Get(AI_MATKEY_NAME, name) == AI_SUCCESS) m.name = name.C_Str();
      int two_sided = 0;
      if (src.Get(AI_MATKEY_TWOSIDED, two_sided) == AI_SUCCESS) m.two_sided = two_sided != 0;
      aiColor4D base;
      aiColor3D diffuse, emissive;
      float value = 0.0f;
      if (src.Get(AI_MATKEY_BASE_COLOR, base) == AI_SUCCESS) m.base_color = glm::vec4(base.r, base.g, base.b, base.a);
      if (src.Get(AI_MATKEY_COLOR_DIFFUSE, diffuse) == AI_SUCCESS) m.diffuse = glm::vec3(diffuse.r, diffuse.g, diffuse.b);
      if (src.Get(AI_MATKEY_OPACITY, value) == AI_SUCCESS) m.opacity = value;
      if (src.Get(AI_MATKEY_COLOR_EMISSIVE, emissive) == AI_SUCCESS) m.emissive = glm::vec3(emissive.r, emissive.g, emissive.b);
      if (src.Get(AI_MATKEY_SHININESS, value) == AI_SUCCESS) m.shininess = value;
      if (src.Get(AI_MATKEY_METALLIC_FACTOR, value) == AI_SUCCESS) m.metallic = value;
      if (src.Get(AI_MATKEY_ROUGHNESS_FACTOR, value) == AI_SUCCESS) m.roughness = value;
      m.base_color_texture = texture_path(src, {aiTextureType_BASE_COLOR, aiTextureType_DIFFUSE});
      m.normal_texture = texture_path(src, {aiTextureType_NORMALS, aiTextureType_NORMAL_CAMERA, aiTextureType_HEIGHT});
      m.emissive_texture = texture_path(src, {aiTextureType_EMISSION_COLOR, aiTextureType_EMISSIVE});
      m.specular_texture = texture_path(src, {aiTextureType_SPECULAR});
      m.metalness_texture = texture_path(src, {aiTextureType_METALNESS});
      m.roughness_texture = texture_path(src, {aiTextureType_DIFFUSE_ROUGHNESS});
      m.occlusion_texture = texture_path(src, {aiTextureType_AMBIENT_OCCLUSION, aiTextureType_LIGHTMAP});
      m.opacity_texture = texture_path(src, {aiTextureType_OPACITY});
      asset.materials.push_back(materials_.convert(m, asset.materials.size()));
    }
  }

  // Textures the file embeds: "*3", or (FBX) a file name whose bytes it holds.
  EmbeddedTextures embedded_textures() const {
    return {
        [this](const std::string& written) { return written[0] == '*' || scene_->GetEmbeddedTexture(written.c_str()); },
        [this](const std::string& written, std::string& error) {
          const aiTexture* embedded = scene_->GetEmbeddedTexture(written.c_str());
          if (!embedded) {
            error = "no embedded texture " + written;
            return std::vector<std::uint8_t>{};
          }
          if (embedded->mHeight != 0) {
            error = "an uncompressed embedded texture, which Atrium does not read";
            return std::vector<std::uint8_t>{};
          }
          const auto* data = reinterpret_cast<const std::uint8_t*>(embedded->pcData);
          return std::vector<std::uint8_t>(data, data + embedded->mWidth);
        },
    };
  }

  fs::path path_;
  std::string name_;
  AssetManager& assets_;
  MemoryBudget budget_;
  const aiScene* scene_ = nullptr;
  ModelImport result_;
  ClassicMaterials materials_;
  std::size_t triangles_read_ = 0;
  DroppedTriangles dropped_;
};

}  // namespace

ModelImport import_assimp(const std::filesystem::path& path, AssetManager& assets, const ImportOptions& options) {
  return refuse_out_of_memory(path, [&] { return AssimpImporter(path, assets, options).run(); });
}

}  // namespace atrium::assets
