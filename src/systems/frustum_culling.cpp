#include "systems/frustum_culling.hpp"

#include <vector>

#include "components/bounds.hpp"
#include "components/frame_resources.hpp"
#include "components/visibility.hpp"

namespace atrium {

bool faces_away(const MeshletBounds& meshlet, glm::vec3 eye) {
  // dot(normalize(d), axis) >= cutoff without the division; an eye on the apex cannot tell.
  const glm::vec3 d = meshlet.cone_apex - eye;
  const float distance = glm::length(d);
  return distance > 0.0f && glm::dot(d, meshlet.cone_axis) >= meshlet.cone_cutoff * distance;
}

namespace {

// Sets or clears bit kInView of state, keeping what occlusion culling learnt
// last frame while in view and forgetting what it revealed. What leaves the
// view forgets it was shown: when it comes back it is tested before it is drawn.
void mark_in_view(std::uint8_t& state, bool in_view) {
  state = in_view ? static_cast<std::uint8_t>((state & seen::kLastFrame) | seen::kInView) : std::uint8_t{0};
}

// Sizes a per-primitive or per-meshlet state list; a list of another size
// belonged to another mesh, and starts over.
void fit(std::vector<std::uint8_t>& states, std::size_t size) {
  if (states.size() != size) states.assign(size, 0);
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
  CullingStats stats;
  registry.view<WorldBounds, Visibility>().each([&](const WorldBounds& bounds, Visibility& visibility) {
    ++stats.objects;
    stats.primitives += bounds.primitives.size();
    fit(visibility.primitives, bounds.primitives.size());
    fit(visibility.meshlets, bounds.meshlets.size());
    const bool any_in_view = !bounds.empty && (!culling || intersects(frustum, bounds.min, bounds.max));
    bool any = false;
    for (std::uint32_t p = 0; p < bounds.primitives.size(); ++p) {
      const Box& box = bounds.primitives[p];
      bool in_view = any_in_view && !box.empty && (!culling || intersects(frustum, box.min, box.max));
      const std::uint32_t first = bounds.meshlet_offsets[p], last = bounds.meshlet_offsets[p + 1];
      // A box wholly in view holds meshlets wholly in view: only their cones are left to test.
      const bool wholly_in_view = first != last && in_view && culling && contains(frustum, box.min, box.max);
      bool meshlet_in_view = false;
      for (std::uint32_t m = first; m < last; ++m) {
        const MeshletBounds& world = bounds.meshlets[m];
        bool visible = in_view;
        if (visible && culling) {
          ++stats.meshlets;
          visible = (wholly_in_view || intersects(frustum, world.center, world.radius)) && !faces_away(world, view.camera_position);
          stats.meshlets_visible += visible;
        }
        mark_in_view(visibility.meshlets[m], visible);
        meshlet_in_view = meshlet_in_view || visible;
      }
      if (first != last) in_view = meshlet_in_view;
      mark_in_view(visibility.primitives[p], in_view);
      stats.primitives_visible += in_view;
      any = any || in_view;
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
