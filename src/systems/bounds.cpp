#include "systems/bounds.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "assets/asset_manager.hpp"
#include "components/bounds.hpp"
#include "components/mesh_instance.hpp"
#include "components/transform.hpp"

namespace atrium {
namespace {

// Whether a linear map is a rotation times a uniform scale (it keeps angles).
bool keeps_angles(const glm::mat3& m) {
  const float a = glm::dot(m[0], m[0]), b = glm::dot(m[1], m[1]), c = glm::dot(m[2], m[2]);
  const float tolerance = 1e-4f * std::max({a, b, c});
  return std::abs(a - b) <= tolerance && std::abs(a - c) <= tolerance && std::abs(glm::dot(m[0], m[1])) <= tolerance &&
         std::abs(glm::dot(m[0], m[2])) <= tolerance && std::abs(glm::dot(m[1], m[2])) <= tolerance;
}

void compute_boxes(const assets::AssetManager& assets, const MeshInstance& instance, const glm::mat4& model, WorldBounds& bounds) {
  bounds.model = model;
  bounds.asset = instance.asset;
  bounds.mesh = instance.mesh;
  bounds.primitives.clear();
  bounds.meshlets.clear();
  bounds.meshlet_offsets.assign(1, 0);
  Box whole;
  const assets::MeshAsset& asset = assets.mesh_asset(instance.asset);
  const glm::mat3 linear(model);
  const float scale = std::max({glm::length(linear[0]), glm::length(linear[1]), glm::length(linear[2])});
  const bool similarity = glm::determinant(linear) > 0.0f && keeps_angles(linear);
  if (instance.mesh < asset.meshes.size()) {
    for (const assets::Primitive& p : asset.meshes[instance.mesh].primitives) {
      for (const assets::Meshlet& m : p.meshlets) {
        MeshletBounds world;
        world.center = glm::vec3(model * glm::vec4(m.center, 1.0f));
        world.radius = m.radius * scale;
        if (similarity) {
          world.cone_apex = glm::vec3(model * glm::vec4(m.cone_apex, 1.0f));
          world.cone_axis = glm::normalize(linear * m.cone_axis);
          world.cone_cutoff = m.cone_cutoff;
        }
        bounds.meshlets.push_back(world);
      }
      bounds.meshlet_offsets.push_back(static_cast<std::uint32_t>(bounds.meshlets.size()));
      Box box;
      if (!p.indices.empty()) box.add_box(model, p.bounds_min, p.bounds_max);
      bounds.primitives.push_back(box);
      whole.add(box);
    }
  }
  static_cast<Box&>(bounds) = whole;
}

}  // namespace

void update_bounds(ecs::Registry& registry) {
  const auto& assets = registry.resource<assets::AssetManager>();
  if (!registry.try_resource<SceneBounds>()) registry.set_resource<SceneBounds>();
  Box scene;
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
    scene.add(bounds);
  });
  // A scene that draws nothing keeps the box it declared (the World seeds
  // SceneBounds with it), so that the camera and the systems placing things
  // in it still have a scale.
  if (!scene.empty) registry.resource<SceneBounds>() = SceneBounds{scene};
}

void register_bounds(ecs::Scheduler& scheduler) { scheduler.add(ecs::Phase::PostUpdate, "bounds", update_bounds); }

}  // namespace atrium
