#include "systems/frustum_culling.hpp"

#include <vector>

#include "components/bounds.hpp"
#include "components/frame_resources.hpp"
#include "components/visibility.hpp"
#include "assets/asset_manager.hpp"

namespace atrium {

Frustum frustum_of(const glm::mat4& m) {
  // Gribb and Hartmann: a clip-space bound is a plane over the matrix's rows.
  const glm::vec4 x{m[0][0], m[1][0], m[2][0], m[3][0]};
  const glm::vec4 y{m[0][1], m[1][1], m[2][1], m[3][1]};
  const glm::vec4 z{m[0][2], m[1][2], m[2][2], m[3][2]};
  const glm::vec4 w{m[0][3], m[1][3], m[2][3], m[3][3]};
  // -w <= x, y <= w; 0 <= z <= w holds for both depth directions.
  return {{w + x, w - x, w + y, w - y, z, w - z}};
}

bool intersects(const Frustum& frustum, glm::vec3 min, glm::vec3 max) {
  for (const glm::vec4& plane : frustum.planes) {
    // The box's corner farthest along the plane's normal.
    const glm::vec3 corner{plane.x >= 0.0f ? max.x : min.x, plane.y >= 0.0f ? max.y : min.y, plane.z >= 0.0f ? max.z : min.z};
    if (glm::dot(glm::vec3(plane), corner) + plane.w < 0.0f) return false;
  }
  return true;
}

bool intersects(const Frustum& frustum, glm::vec3 center, float radius) {
  for (const glm::vec4& plane : frustum.planes) {
    // Planes from a matrix are not unit length: scale the radius with them.
    if (glm::dot(glm::vec3(plane), center) + plane.w < -radius * glm::length(glm::vec3(plane))) return false;
  }
  return true;
}

bool faces_away(const MeshletBounds& meshlet, glm::vec3 eye) {
  return glm::dot(glm::normalize(meshlet.cone_apex - eye), meshlet.cone_axis) >= meshlet.cone_cutoff;
}

namespace {

// Culls primitive p's meshlets; appends the runs of visible ones to `ranges`.
// Returns whether any is visible.
bool cull_meshlets(const Frustum& frustum, glm::vec3 eye, const assets::Primitive& primitive, const WorldBounds& bounds,
                   std::uint32_t p, std::vector<VisibleRange>& ranges, CullingStats& stats) {
  bool any = false;
  for_each_meshlet_run(
      primitive.meshlets, bounds.meshlets.data() + bounds.meshlet_offsets[p],
      [&](const MeshletBounds& world) {
        ++stats.meshlets;
        const bool visible = intersects(frustum, world.center, world.radius) && !faces_away(world, eye);
        stats.meshlets_visible += visible;
        return visible;
      },
      [&](std::uint32_t first_index, std::uint32_t index_count) {
        ranges.push_back({p, first_index, index_count});
        any = true;
      });
  return any;
}

}  // namespace

void update_frustum_culling(ecs::Registry& registry) {
  std::vector<ecs::Entity> missing;
  registry.view<WorldBounds>().each([&](ecs::Entity entity, const WorldBounds&) {
    if (!registry.has<Visibility>(entity)) missing.push_back(entity);
  });
  for (const ecs::Entity entity : missing) registry.add<Visibility>(entity);
  const bool culling = registry.resource<RendererSettings>().frustum_culling;
  const ViewState& view = registry.resource<ViewState>();
  const Frustum frustum = frustum_of(view.view_projection);
  const auto& assets = registry.resource<assets::AssetManager>();
  CullingStats stats;
  registry.view<WorldBounds, Visibility>().each([&](const WorldBounds& bounds, Visibility& visibility) {
    ++stats.objects;
    stats.primitives += bounds.primitives.size();
    visibility.any = !bounds.empty && (!culling || intersects(frustum, bounds.min, bounds.max));
    visibility.primitives.assign(bounds.primitives.size(), 0);
    visibility.ranges.clear();
    if (!visibility.any) return;
    const auto& primitives = assets.mesh_asset(bounds.asset).meshes.at(bounds.mesh).primitives;
    bool any = false;
    for (std::uint32_t p = 0; p < bounds.primitives.size(); ++p) {
      const Box& box = bounds.primitives[p];
      bool visible = !box.empty && (!culling || intersects(frustum, box.min, box.max));
      if (visible && culling && !primitives[p].meshlets.empty()) {
        visible = cull_meshlets(frustum, view.camera_position, primitives[p], bounds, p, visibility.ranges, stats);
      }
      visibility.primitives[p] = visible;
      stats.primitives_visible += visible;
      any = any || visible;
    }
    visibility.any = any;
    stats.objects_visible += any;
  });
  registry.set_resource<CullingStats>(stats);
}

void register_frustum_culling(ecs::Scheduler& scheduler) {
  scheduler.add(ecs::Phase::PostUpdate, "frustum_culling", update_frustum_culling);
}

}  // namespace atrium
