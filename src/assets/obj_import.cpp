#include "assets/obj_import.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <unordered_map>

#include <tiny_obj_loader.h>

#include "assets/classic_materials.hpp"
#include "assets/file_lookup.hpp"
#include "assets/load_budget.hpp"

namespace atrium::assets {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// tinyobjloader's parse holds a file's statements several times over (each
// face corner as three ints in two lists, besides the text): the budget
// asks for this many bytes per byte of OBJ before parsing starts.
constexpr std::size_t kParseBytesPerFileByte = 24;

// A face corner's position, normal and texture coordinate indices (-1: none).
struct Corner {
  int position, normal, uv;
  bool operator==(const Corner&) const = default;
};
struct CornerHash {
  std::size_t operator()(const Corner& c) const {
    const std::uint64_t h = static_cast<std::uint64_t>(static_cast<std::uint32_t>(c.position)) * 0x9E3779B97F4A7C15ull ^
                            static_cast<std::uint64_t>(static_cast<std::uint32_t>(c.normal)) * 0xC2B2AE3D27D4EB4Full ^
                            static_cast<std::uint32_t>(c.uv);
    return static_cast<std::size_t>(h ^ (h >> 32));
  }
};

bool space(char c) { return c == ' ' || c == '\t'; }

// Calls `line(number, text)` for each line as tinyobjloader splits them (at
// \n, \r and \r\n); stops early when `line` returns false.
template <typename Line>
void for_each_line(std::string_view text, Line&& line) {
  std::size_t number = 1;
  for (std::size_t start = 0; start < text.size();) {
    std::size_t end = text.find_first_of("\r\n", start);
    if (end == std::string_view::npos) end = text.size();
    if (!line(number++, text.substr(start, end - start))) return;
    start = end + (end + 1 < text.size() && text[end] == '\r' && text[end + 1] == '\n' ? 2 : 1);
  }
}

// Refuses, in a few words, a file whose faces would cost more than
// kMaxObjClipWork to cut into triangles (quads and triangles cost nothing).
std::string clip_work_problem(std::string_view text) {
  std::uint64_t work = 0;  // 64 bits on wasm32 too: a 70,000-gon squared passes 2^32
  std::size_t largest = 0, largest_line = 0, last_line = 0;
  for_each_line(text, [&](std::size_t number, std::string_view line) {
    std::size_t i = 0;
    while (i < line.size() && space(line[i])) ++i;
    if (i + 1 >= line.size() || line[i] != 'f' || !space(line[i + 1])) return true;
    std::size_t corners = 0;
    for (++i; i < line.size() && line[i] != '\0';) {
      while (i < line.size() && space(line[i])) ++i;
      if (i >= line.size() || line[i] == '\0') break;
      ++corners;
      while (i < line.size() && !space(line[i]) && line[i] != '\0') ++i;
    }
    if (corners > 4) work += std::uint64_t{corners} * corners;
    if (corners > largest) largest = corners, largest_line = number;
    last_line = number;
    return work <= kMaxObjClipWork;
  });
  if (work <= kMaxObjClipWork) return "";
  return "its faces are too large to cut into triangles: by line " + std::to_string(last_line) + " their corners, squared and summed, exceed " +
         std::to_string(kMaxObjClipWork) + " (the largest, on line " + std::to_string(largest_line) + ", has " + std::to_string(largest) + ")";
}

// Which statements each material of a library writes (tinyobjloader fills
// absent values with defaults that an exponent or factor could also be).
using StatedKeys = std::map<std::string, std::set<std::string>>;

void read_stated_keys(std::string_view text, StatedKeys& stated) {
  std::string material;
  for_each_line(text, [&](std::size_t, std::string_view line) {
    std::size_t i = 0;
    while (i < line.size() && space(line[i])) ++i;
    std::size_t end = i;
    while (end < line.size() && !space(line[end])) ++end;
    const std::string key(line.substr(i, end - i));
    if (key == "newmtl") {
      while (end < line.size() && space(line[end])) ++end;
      material = std::string(line.substr(end));
      // tinyobjloader keeps a name up to its first space or tab.
      material = material.substr(0, material.find_first_of(" \t"));
    } else if (!key.empty()) {
      stated[material].insert(key);
    }
    return true;
  });
}

// Material libraries found as textures are (file_lookup.hpp), read within
// the budget; one warning per library that cannot be read.
class MaterialLibraries : public tinyobj::MaterialReader {
 public:
  MaterialLibraries(fs::path folder, std::size_t limit) : folder_(std::move(folder)), limit_(limit) {}

  bool operator()(const std::string& written, std::vector<tinyobj::material_t>* materials, std::map<std::string, int>* names, std::string*,
                  std::string*) override {
    const FoundFile found = find_named_file(folder_, written);
    const FileBytes read = found.path ? read_file_within(*found.path, limit_) : FileBytes{{}, not_a_file(folder_ / written)};
    if (!read.problem.empty()) {
      warnings.push_back(unreadable_warning(written, read.problem) + "; what it holds is left out");
      return false;
    }
    if (!found.how.empty()) warnings.push_back(found_elsewhere_warning(written, found.how, *found.path, folder_));
    const std::string text(read.bytes.begin(), read.bytes.end());
    read_stated_keys(text, stated);
    std::istringstream stream(text);
    std::string warning, error;
    tinyobj::LoadMtl(names, materials, &stream, &warning, &error);
    return true;
  }

  std::vector<std::string> warnings;
  StatedKeys stated;

 private:
  fs::path folder_;
  std::size_t limit_;
};

class ObjImporter {
 public:
  ObjImporter(const fs::path& path, AssetManager& assets, const ImportOptions& options)
      : path_(path),
        name_(path.string()),
        assets_(assets),
        budget_(options.memory_limit),
        materials_(path, options.convention.value_or(MaterialConvention::Phong), assets, options, result_) {
    budget_.set_file(name_);
  }

  ModelImport run() {
    const auto start = Clock::now();
    FileBytes file = read_file_within(path_, budget_.limit());
    if (!file.problem.empty()) fail(file.problem);
    budget_.require(budget_.bytes(file.bytes.size(), kParseBytesPerFileByte, "parsing its text"), "parsing its text");
    std::string text(file.bytes.begin(), file.bytes.end());
    file.bytes = {};
    if (const std::string problem = clip_work_problem(text); !problem.empty()) fail(problem);

    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    MaterialLibraries libraries(path_.parent_path().empty() ? fs::path(".") : path_.parent_path(), budget_.limit());
    std::string warning, error;
    {
      std::istringstream stream(std::move(text));
      if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warning, &error, &stream, &libraries, true, false)) {
        fail(parse_problem(error));
      }
    }
    for (std::string& line : libraries.warnings) warn(std::move(line));
    if (attrib.vertices.empty()) fail("it has no vertices ('v' lines)");

    MeshAsset asset;
    asset.name = path_.filename().string();
    for (std::size_t i = 0; i < materials.size(); ++i) {
      asset.materials.push_back(materials_.convert(classic(materials[i], libraries.stated[materials[i].name]), i));
    }
    for (std::size_t s = 0; s < shapes.size(); ++s) read_shape(asset, attrib, shapes[s], s);
    if (triangles_read_ == 0) fail("it has no faces ('f' lines) with three or more corners");
    for (const std::string& line : dropped_triangle_lines(dropped_, triangles_read_)) warn(line);
    result_.timings.parse_seconds = seconds_since(start);
    const auto decode_start = Clock::now();
    materials_.decode(asset.materials);
    result_.timings.decode_seconds = seconds_since(decode_start);
    // No nodes: each shape is one instance where the file puts it.
    Box bounds;
    for (std::uint32_t m = 0; m < asset.meshes.size(); ++m) {
      if (asset.meshes[m].primitives.empty()) continue;
      result_.instances.push_back({MeshAssetHandle{}, m, Transform{}});
      for (const Primitive& p : asset.meshes[m].primitives) bounds.add_box(glm::mat4(1.0f), p.bounds_min, p.bounds_max);
    }
    result_.bounds = bounds;
    result_.asset = assets_.add_mesh_asset(std::move(asset), fs::weakly_canonical(path_).string());
    return std::move(result_);
  }

 private:
  [[noreturn]] void fail(const std::string& problem) const { throw ImportError(name_ + ": " + problem); }
  void warn(const std::string& problem) { result_.warnings.push_back(name_ + ": " + problem); }

  // tinyobjloader's refusal in Atrium's words: it stops at a face, line or
  // point ('f', 'l', 'p', 'vw') with an index of zero or not a number, and
  // says on which line.
  static std::string parse_problem(const std::string& error) {
    const std::size_t quote = error.find('`'), at = error.find("line ", error.find('('));
    if (error.rfind("Failed parse `", 0) != 0 || quote == std::string::npos || at == std::string::npos) {
      const std::string first = error.substr(0, error.find('\n'));
      return first.empty() ? "not an OBJ file Atrium can read" : first;
    }
    const std::string statement = error.substr(quote + 1, error.find('\'', quote) - quote - 1);
    const std::string line = error.substr(at + 5, error.find_first_not_of("0123456789", at + 5) - at - 5);
    return "line " + line + ": an '" + statement + "' statement with an index of zero or not a number";
  }

  // An MTL material as the shared conventions read it; `stated`: the
  // statements its library wrote for it.
  static ClassicMaterial classic(const tinyobj::material_t& src, const std::set<std::string>& stated) {
    ClassicMaterial m;
    m.name = src.name;
    m.diffuse = glm::vec3(src.diffuse[0], src.diffuse[1], src.diffuse[2]);
    m.opacity = src.dissolve;  // `d`, or 1 - `Tr`
    m.emissive = glm::vec3(src.emission[0], src.emission[1], src.emission[2]);
    if (stated.contains("Ns")) m.shininess = src.shininess;
    if (stated.contains("Pm")) m.metallic = src.metallic;
    if (stated.contains("Pr")) m.roughness = src.roughness;
    const auto texture = [](const std::string& name) { return name.empty() ? std::nullopt : std::optional<std::string>(name); };
    m.base_color_texture = texture(src.diffuse_texname);
    m.normal_texture = texture(src.normal_texname.empty() ? src.bump_texname : src.normal_texname);
    m.emissive_texture = texture(src.emissive_texname);
    m.specular_texture = texture(src.specular_texname);
    m.metalness_texture = texture(src.metallic_texname);
    m.roughness_texture = texture(src.roughness_texname);
    m.opacity_texture = texture(src.alpha_texname);
    return m;
  }

  // One mesh per shape ('o' or 'g'), one primitive per material its faces use.
  void read_shape(MeshAsset& asset, const tinyobj::attrib_t& attrib, const tinyobj::shape_t& shape, std::size_t index) {
    const std::string what = "shape " + std::to_string(index) + (shape.name.empty() ? "" : " '" + shape.name + "'");
    Mesh mesh;
    mesh.name = shape.name.empty() ? "mesh " + std::to_string(index) : shape.name;
    const tinyobj::mesh_t& source = shape.mesh;
    const std::size_t faces = source.num_face_vertices.size();
    if (source.indices.size() != faces * 3 || source.material_ids.size() != faces) fail(what + ": its faces are not triangles");
    std::map<int, std::vector<std::size_t>> faces_of_material;
    for (std::size_t f = 0; f < faces; ++f) faces_of_material[source.material_ids[f]].push_back(f);
    const std::size_t positions = attrib.vertices.size() / 3, normals = attrib.normals.size() / 3, uvs = attrib.texcoords.size() / 2;
    const bool colors = attrib.colors.size() == attrib.vertices.size();
    for (const auto& [material_id, face_list] : faces_of_material) {
      Geometry geometry;
      // One vertex per distinct (position, normal, texture coordinate).
      std::unordered_map<Corner, std::uint32_t, CornerHash> vertex_of;
      std::vector<int> position_of_vertex;
      bool has_normals = true;
      geometry.indices.reserve(budget_.bytes(face_list.size() * 3, sizeof(std::uint32_t), what) / sizeof(std::uint32_t));
      for (const std::size_t f : face_list) {
        for (std::size_t k = 0; k < 3; ++k) {
          const tinyobj::index_t& corner = source.indices[f * 3 + k];
          check(corner.vertex_index >= 0 && static_cast<std::size_t>(corner.vertex_index) < positions, what, f, "vertex", corner.vertex_index, positions);
          check(corner.normal_index == -1 || (corner.normal_index >= 0 && static_cast<std::size_t>(corner.normal_index) < normals), what, f,
                "normal", corner.normal_index, normals);
          check(corner.texcoord_index == -1 || (corner.texcoord_index >= 0 && static_cast<std::size_t>(corner.texcoord_index) < uvs), what, f,
                "texture coordinate", corner.texcoord_index, uvs);
          const auto [it, added] = vertex_of.try_emplace(Corner{corner.vertex_index, corner.normal_index, corner.texcoord_index},
                                                         static_cast<std::uint32_t>(geometry.vertices.size()));
          if (added) {
            geometry.vertices.push_back(vertex(attrib, corner, colors));
            position_of_vertex.push_back(corner.vertex_index);
            has_normals &= corner.normal_index >= 0;
          }
          geometry.indices.push_back(it->second);
        }
      }
      (void)budget_.bytes(geometry.vertices.size(), sizeof(Vertex), what);
      triangles_read_ += geometry.indices.size() / 3;
      dropped_ += drop_unusable_triangles(geometry.vertices, geometry.indices);
      if (geometry.indices.empty()) continue;
      if (!has_normals) smooth_normals_by_position(geometry, position_of_vertex, positions);
      if (repair_normals(geometry.vertices, geometry.indices)) warn(what + " has zero-length or invalid normals; they were regenerated");
      generate_tangents(geometry);
      const bool named = material_id >= 0 && static_cast<std::size_t>(material_id) < asset.materials.size();
      const std::uint32_t material = named ? static_cast<std::uint32_t>(material_id) : materials_.default_material(asset);
      mesh.primitives.push_back(add_geometry(asset, std::move(geometry), material));
    }
    asset.meshes.push_back(std::move(mesh));
  }

  // A corner's index into a list of `count` ('v', 'vn' or 'vt' lines), where
  // the file may give it relative to the end (negative).
  void check(bool ok, const std::string& what, std::size_t face, const char* kind, int index, std::size_t count) const {
    if (ok) return;
    const std::string where = what + ": triangle " + std::to_string(face) + " names ";
    if (index < 0) fail(where + "a " + kind + " before the first");
    fail(where + kind + " " + std::to_string(index + 1) + " of " + std::to_string(count));
  }

  static Vertex vertex(const tinyobj::attrib_t& attrib, const tinyobj::index_t& corner, bool colors) {
    Vertex v;
    const std::size_t p = static_cast<std::size_t>(corner.vertex_index) * 3;
    v.position = {attrib.vertices[p], attrib.vertices[p + 1], attrib.vertices[p + 2]};
    if (corner.normal_index >= 0) {
      const std::size_t n = static_cast<std::size_t>(corner.normal_index) * 3;
      v.normal = {attrib.normals[n], attrib.normals[n + 1], attrib.normals[n + 2]};
    } else {
      v.normal = glm::vec3(0.0f);
    }
    if (corner.texcoord_index >= 0) {
      const std::size_t t = static_cast<std::size_t>(corner.texcoord_index) * 2;
      // OBJ's V points up the image, glTF's (and Atrium's) down.
      v.uv0 = {attrib.texcoords[t], 1.0f - attrib.texcoords[t + 1]};
    }
    if (colors) {
      for (std::size_t k = 0; k < 3; ++k) {
        v.color[k] = static_cast<std::uint16_t>(std::lround(std::clamp(attrib.colors[p + k], 0.0f, 1.0f) * 65535.0f));
      }
    }
    return v;
  }

  // A file without normals is smooth where its faces share a position ('v'),
  // across texture seams too, as modelling tools draw it.
  static void smooth_normals_by_position(Geometry& geometry, const std::vector<int>& position_of_vertex, std::size_t positions) {
    // Per vertex first: where a position's faces cancel out (a zero sum), its
    // vertices keep the normal of their own faces.
    generate_normals(geometry);
    std::unordered_map<int, glm::vec3> sum;
    sum.reserve(std::min(positions, geometry.vertices.size()));
    for (std::size_t t = 0; t + 2 < geometry.indices.size(); t += 3) {
      const std::uint32_t a = geometry.indices[t], b = geometry.indices[t + 1], c = geometry.indices[t + 2];
      // Area-weighted: the cross product's length is twice the area.
      const glm::vec3 face = glm::cross(geometry.vertices[b].position - geometry.vertices[a].position,
                                        geometry.vertices[c].position - geometry.vertices[a].position);
      for (const std::uint32_t v : {a, b, c}) sum[position_of_vertex[v]] += face;
    }
    for (std::size_t v = 0; v < geometry.vertices.size(); ++v) {
      const auto it = sum.find(position_of_vertex[v]);
      if (it != sum.end() && glm::length(it->second) > 0.0f) geometry.vertices[v].normal = glm::normalize(it->second);
    }
  }


  fs::path path_;
  std::string name_;
  AssetManager& assets_;
  MemoryBudget budget_;
  ModelImport result_;
  ClassicMaterials materials_;
  std::size_t triangles_read_ = 0;
  DroppedTriangles dropped_;
};

}  // namespace

ModelImport import_obj(const std::filesystem::path& path, AssetManager& assets, const ImportOptions& options) {
  return refuse_out_of_memory(path, [&] { return ObjImporter(path, assets, options).run(); });
}

}  // namespace atrium::assets
