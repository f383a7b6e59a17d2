// Loading a large glTF: 1,048,576 triangles in 8 meshes and 50 textures of
// 1024x1024 (25 PNG, 25 JPEG), generated once into the build folder. Measures
// parse, image decode with 1 thread and with every core, and GPU upload on a
// headless context.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <benchmark/benchmark.h>
#include <stb_image_write.h>
#include <tiny_gltf.h>

#include "assets/gltf_import.hpp"
#include "render/gpu_assets.hpp"
#include "gfx/context.hpp"

namespace {
namespace fs = std::filesystem;
using namespace atrium;

constexpr int kMeshes = 8, kGrid = 256, kTextures = 50, kTextureSize = 1024;

void append_bytes(std::vector<unsigned char>& buffer, const void* data, std::size_t bytes) {
  while (buffer.size() % 4) buffer.push_back(0);
  buffer.insert(buffer.end(), static_cast<const unsigned char*>(data), static_cast<const unsigned char*>(data) + bytes);
}

// stb's encoders write in many pieces: no padding between them.
void write_stream(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<unsigned char>*>(context);
  out->insert(out->end(), static_cast<unsigned char*>(data), static_cast<unsigned char*>(data) + size);
}

fs::path large_model() {
  const fs::path folder = fs::path(ATRIUM_BENCH_DATA_DIR) / "large-model";
  const fs::path path = folder / "large.gltf";
  if (fs::exists(path)) return path;
  fs::create_directories(folder);
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.buffers.emplace_back();
  model.buffers[0].uri = "large.bin";
  auto& bytes = model.buffers[0].data;
  auto add_view = [&](std::size_t offset, std::size_t length) {
    tinygltf::BufferView v;
    v.buffer = 0;
    v.byteOffset = offset;
    v.byteLength = length;
    model.bufferViews.push_back(v);
    return static_cast<int>(model.bufferViews.size() - 1);
  };
  // Textures: smooth patterns, so that PNG and JPEG sizes are realistic.
  std::vector<unsigned char> pixels(static_cast<std::size_t>(kTextureSize) * kTextureSize * 3);
  for (int t = 0; t < kTextures; ++t) {
    for (int y = 0; y < kTextureSize; ++y) {
      for (int x = 0; x < kTextureSize; ++x) {
        unsigned char* p = &pixels[(static_cast<std::size_t>(y) * kTextureSize + x) * 3];
        p[0] = static_cast<unsigned char>(128 + 100 * std::sin(x * 0.02 + t));
        p[1] = static_cast<unsigned char>(128 + 100 * std::sin(y * 0.03 + t * 0.5));
        p[2] = static_cast<unsigned char>((x ^ y ^ t) & 0xff);
      }
    }
    std::vector<unsigned char> encoded;
    const bool png = t % 2 == 0;
    if (png) stbi_write_png_to_func(write_stream, &encoded, kTextureSize, kTextureSize, 3, pixels.data(), kTextureSize * 3);
    else stbi_write_jpg_to_func(write_stream, &encoded, kTextureSize, kTextureSize, 3, pixels.data(), 90);
    const std::size_t offset = (bytes.size() + 3) / 4 * 4;
    append_bytes(bytes, encoded.data(), encoded.size());
    tinygltf::Image image;
    image.bufferView = add_view(offset, encoded.size());
    image.mimeType = png ? "image/png" : "image/jpeg";
    model.images.push_back(image);
    tinygltf::Texture texture;
    texture.source = t;
    model.textures.push_back(texture);
  }
  // Meshes: tessellated grids, each with a material using one or two textures.
  for (int m = 0; m < kMeshes; ++m) {
    std::vector<float> positions, normals, uvs;
    std::vector<std::uint32_t> indices;
    for (int j = 0; j <= kGrid; ++j) {
      for (int i = 0; i <= kGrid; ++i) {
        positions.insert(positions.end(), {static_cast<float>(i) / kGrid + m, static_cast<float>(j) / kGrid, 0.0f});
        normals.insert(normals.end(), {0.0f, 0.0f, 1.0f});
        uvs.insert(uvs.end(), {static_cast<float>(i) / kGrid, static_cast<float>(j) / kGrid});
      }
    }
    for (std::uint32_t j = 0; j < kGrid; ++j) {
      for (std::uint32_t i = 0; i < kGrid; ++i) {
        const std::uint32_t a = j * (kGrid + 1) + i;
        indices.insert(indices.end(), {a, a + 1, a + kGrid + 2, a, a + kGrid + 2, a + kGrid + 1});
      }
    }
    tinygltf::Primitive primitive;
    auto accessor = [&](const void* data, std::size_t size, int type, int component, std::size_t count) {
      const std::size_t offset = (bytes.size() + 3) / 4 * 4;
      append_bytes(bytes, data, size);
      tinygltf::Accessor a;
      a.bufferView = add_view(offset, size);
      a.componentType = component;
      a.type = type;
      a.count = count;
      model.accessors.push_back(a);
      return static_cast<int>(model.accessors.size() - 1);
    };
    const std::size_t vertices = positions.size() / 3;
    primitive.attributes["POSITION"] = accessor(positions.data(), positions.size() * 4, TINYGLTF_TYPE_VEC3, TINYGLTF_COMPONENT_TYPE_FLOAT, vertices);
    primitive.attributes["NORMAL"] = accessor(normals.data(), normals.size() * 4, TINYGLTF_TYPE_VEC3, TINYGLTF_COMPONENT_TYPE_FLOAT, vertices);
    primitive.attributes["TEXCOORD_0"] = accessor(uvs.data(), uvs.size() * 4, TINYGLTF_TYPE_VEC2, TINYGLTF_COMPONENT_TYPE_FLOAT, vertices);
    primitive.indices = accessor(indices.data(), indices.size() * 4, TINYGLTF_TYPE_SCALAR, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, indices.size());
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    primitive.material = m;
    tinygltf::Mesh mesh;
    mesh.primitives.push_back(primitive);
    model.meshes.push_back(mesh);
    tinygltf::Node node;
    node.mesh = m;
    model.nodes.push_back(node);
  }
  // Every texture is used: the 8 meshes' materials fill all five slots with
  // textures 0-39, and materials that no mesh uses take 40-49.
  for (int m = 0; m < kMeshes; ++m) {
    tinygltf::Material material;
    material.pbrMetallicRoughness.baseColorTexture.index = m * 5;
    material.pbrMetallicRoughness.metallicRoughnessTexture.index = m * 5 + 1;
    material.normalTexture.index = m * 5 + 2;
    material.occlusionTexture.index = m * 5 + 3;
    material.emissiveTexture.index = m * 5 + 4;
    model.materials.push_back(material);
  }
  for (int t = kMeshes * 5; t < kTextures; ++t) {
    tinygltf::Material extra;
    extra.pbrMetallicRoughness.baseColorTexture.index = t;
    model.materials.push_back(extra);
  }
  model.scenes.emplace_back();
  for (int m = 0; m < kMeshes; ++m) model.scenes[0].nodes.push_back(m);
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToFile(&model, path.string(), false, false, true, false)) {
    std::fprintf(stderr, "cannot write %s\n", path.c_str());
    std::exit(1);
  }
  return path;
}

void BM_ImportLargeGltf(benchmark::State& state) {
  const fs::path path = large_model();
  const auto threads = static_cast<unsigned>(state.range(0));
  double parse = 0, decode = 0;
  std::size_t images = 0, triangles = 0;
  for (auto _ : state) {
    assets::AssetManager assets;
    const assets::ModelImport imported = assets::import_gltf(path, assets, {.decode_threads = threads});
    parse += imported.timings.parse_seconds;
    decode += imported.timings.decode_seconds;
    images = imported.images;
    triangles = 0;
    for (const auto& mesh : assets.mesh_asset(imported.asset).meshes) triangles += assets::triangle_count(mesh);
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["parse_s"] = parse / n;
  state.counters["decode_s"] = decode / n;
  state.counters["images"] = static_cast<double>(images);
  state.counters["triangles"] = static_cast<double>(triangles);
}
BENCHMARK(BM_ImportLargeGltf)->Arg(1)->Arg(2)
    ->Unit(benchmark::kMillisecond)->Iterations(3)->UseRealTime();

void BM_UploadLargeGltf(benchmark::State& state) {
  const fs::path path = large_model();
  const auto context = gfx::HeadlessContext::create();
  assets::AssetManager assets;
  (void)assets::import_gltf(path, assets);
  for (auto _ : state) {
    render::GpuAssets gpu;
    gpu.upload(assets);
    glFinish();
  }
  state.SetLabel(context->info().renderer);
}
BENCHMARK(BM_UploadLargeGltf)->Unit(benchmark::kMillisecond)->Iterations(3)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
