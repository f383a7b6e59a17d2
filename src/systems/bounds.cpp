#include "systems/bounds.hpp"

#include <vector>

#include "assets/asset_manager.hpp"
#include "components/bounds.hpp"
#include "components/mesh_instance.hpp"
#include "components/transform.hpp"

namespace atrium {
namespace {

void compute_boxes(const assets::AssetManager& assets, const MeshInstance& instance, const glm::mat4& model, WorldBounds& bounds) {
  bounds.model = model;
  bounds.asset = instance.asset;
  bounds.mesh = instance.mesh;
  bounds.primitives.clear();
  assets::Bounds whole;
  const assets::MeshAsset& asset = assets.mesh_asset(instance.asset);
  if (instance.mesh < asset.meshes.size()) {
    for (const assets::Primitive& p : asset.meshes[instance.mesh].primitives) {
      assets::Bounds box;
      if (!p.indices.empty()) box.add_box(model, p.bounds_min, p.bounds_max);
      bounds.primitives.push_back({box.min, box.max, box.empty});
      if (box.empty) continue;
      whole.add(box.min);
      whole.add(box.max);
    }
  }
  bounds.min = whole.min;
  bounds.max = whole.max;
  bounds.empty = whole.empty;
}

}  // namespace

void update_bounds(ecs::Registry& registry) {
  const auto& assets = registry.resource<assets::AssetManager>();
  if (!registry.try_resource<SceneBounds>()) registry.set_resource<SceneBounds>();
  assets::Bounds scene;
  std::vector<ecs::Entity> missing;
  registry.view<Transform, MeshInstance>().each([&](ecs::Entity entity, const Transform&, const MeshInstance&) {
    if (!registry.has<WorldBounds>(entity)) missing.push_back(entity);
  });
  for (const ecs::Entity entity : missing) registry.add<WorldBounds>(entity);
  registry.view<Transform, MeshInstance, WorldBounds>().each([&](const Transform& transform, const MeshInstance& instance,
                                                                 WorldBounds& bounds) {
    const glm::mat4 model = to_matrix(transform);
    if (model != bounds.model || instance.asset != bounds.asset || instance.mesh != bounds.mesh) {
      compute_boxes(assets, instance, model, bounds);
    }
    if (bounds.empty) return;
    scene.add(bounds.min);
    scene.add(bounds.max);
  });
  registry.resource<SceneBounds>() = {scene.min, scene.max, scene.empty};
}

void register_bounds(ecs::Scheduler& scheduler) { scheduler.add(ecs::Phase::PostUpdate, "bounds", update_bounds); }

}  // namespace atrium
