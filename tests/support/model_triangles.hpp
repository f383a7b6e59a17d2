// Triangles an imported model draws (every instance's mesh, counted once per
// instance), and the check that a model written by another tool is its glTF
// source (shared by the importer tests).
#pragma once

#include <cstddef>
#include <filesystem>

#include <gtest/gtest.h>

#include "assets/asset_manager.hpp"
#include "assets/gltf_import.hpp"
#include "assets/model_import.hpp"

namespace atrium::testing {

inline std::size_t drawn_triangles(const assets::AssetManager& assets, const assets::ModelImport& model) {
  std::size_t count = 0;
  for (const assets::SceneInstance& instance : model.instances) {
    count += assets::triangle_count(assets.mesh_asset(model.asset).meshes.at(instance.mesh));
  }
  return count;
}

// A model and its glTF source: the same triangles, the same box within
// `tolerance` of its size.
inline void expect_same_model(const std::filesystem::path& file, const std::filesystem::path& source, float tolerance = 1e-3f) {
  assets::AssetManager assets;
  const assets::ModelImport model = assets::import_model(file, assets);
  const assets::ModelImport reference = assets::import_gltf(source, assets);
  EXPECT_EQ(drawn_triangles(assets, model), drawn_triangles(assets, reference)) << file.filename();
  const float size = glm::length(reference.bounds.max - reference.bounds.min);
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_NEAR(model.bounds.min[axis], reference.bounds.min[axis], tolerance * size) << file.filename() << " axis " << axis;
    EXPECT_NEAR(model.bounds.max[axis], reference.bounds.max[axis], tolerance * size) << file.filename() << " axis " << axis;
  }
}

}  // namespace atrium::testing
