#include "render/shadows/shadow_views.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "gfx/depth.hpp"

namespace atrium::shadows {
namespace {

// Near planes in proportion to the light's reach: float depth keeps plenty of
// precision with reversed Z, and nothing closer than this casts a shadow.
constexpr float kNearShare = 0.002f;
constexpr float kMinNear = 0.01f;

glm::vec3 any_perpendicular(glm::vec3 d) { return std::abs(d.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0); }

// A perspective view of `resolution` texels whose centre texels cover the
// half-angle `half_angle`, widened so that kGuardTexels spare texels surround it.
ShadowView perspective_view(glm::vec3 eye, glm::vec3 forward, glm::vec3 up, float half_angle, float radius, int resolution) {
  const float inner = static_cast<float>(resolution - 2 * kGuardTexels);
  const float tan_half = std::tan(half_angle) * static_cast<float>(resolution) / std::max(inner, 1.0f);
  const float near = std::max(kMinNear, radius * kNearShare);
  ShadowView view;
  view.view_projection = gfx::perspective(2.0f * std::atan(tan_half), 1.0f, near, std::max(radius, near * 2.0f)) *
                         glm::lookAt(eye, eye + forward, up);
  view.params = glm::vec4(2.0f * tan_half / static_cast<float>(resolution), 0.0f, 1.0f, 0.0f);
  return view;
}

}  // namespace

int view_count(render::GpuLightKind kind) {
  switch (kind) {
    case render::GpuLightKind::Point: return 6;
    case render::GpuLightKind::Spot: return 1;
    case render::GpuLightKind::Directional: return kCascades;
  }
  return 0;
}

std::array<ShadowView, 6> point_views(const render::GpuLight& light, int resolution) {
  // Face order +X, -X, +Y, -Y, +Z, -Z: shadows.glsl picks a face by the major axis in this order.
  static const std::array<glm::vec3, 6> kForward{glm::vec3(1, 0, 0), glm::vec3(-1, 0, 0), glm::vec3(0, 1, 0),
                                                 glm::vec3(0, -1, 0), glm::vec3(0, 0, 1), glm::vec3(0, 0, -1)};
  static const std::array<glm::vec3, 6> kUp{glm::vec3(0, -1, 0), glm::vec3(0, -1, 0), glm::vec3(0, 0, 1),
                                            glm::vec3(0, 0, -1), glm::vec3(0, -1, 0), glm::vec3(0, -1, 0)};
  std::array<ShadowView, 6> views;
  const glm::vec3 eye(light.position_radius);
  for (std::size_t f = 0; f < 6; ++f) {
    views[f] = perspective_view(eye, kForward[f], kUp[f], glm::radians(45.0f), light.position_radius.w, resolution);
  }
  return views;
}

ShadowView spot_view(const render::GpuLight& light, int resolution) {
  // lights.glsl's cone: clamp(cos * x + y, 0, 1) is zero beyond cos = -y / x.
  const float cos_outer = light.spot.x > 0.0f ? std::clamp(-light.spot.y / light.spot.x, -1.0f, 1.0f) : 0.0f;
  const float half_angle = std::min(std::acos(cos_outer), glm::radians(85.0f));
  const glm::vec3 forward = glm::normalize(glm::vec3(light.direction));
  return perspective_view(glm::vec3(light.position_radius), forward, any_perpendicular(forward), half_angle,
                          light.position_radius.w, resolution);
}

std::array<ShadowView, kCascades> cascade_views(const render::GpuLight& light, const CascadeFrame& frame, int resolution) {
  const glm::vec3 direction = glm::normalize(glm::vec3(light.direction));
  // Light space: looking along the light's rays, rotation only.
  const glm::mat4 light_view = glm::lookAt(glm::vec3(0.0f), direction, any_perpendicular(direction));
  // How far along the rays the scene reaches: every caster lies in this depth range.
  float scene_near = INFINITY, scene_far = -INFINITY;
  for (int c = 0; c < 8; ++c) {
    const glm::vec3 corner((c & 1) ? frame.scene_max.x : frame.scene_min.x, (c & 2) ? frame.scene_max.y : frame.scene_min.y,
                           (c & 4) ? frame.scene_max.z : frame.scene_min.z);
    const float depth = -(light_view * glm::vec4(corner, 1.0f)).z;
    scene_near = std::min(scene_near, depth);
    scene_far = std::max(scene_far, depth);
  }
  const glm::mat4 camera_to_world = glm::inverse(frame.view);
  const float tan_x = 1.0f / frame.projection[0][0], tan_y = 1.0f / frame.projection[1][1];
  std::array<ShadowView, kCascades> views;
  float split_near = frame.near;
  for (int c = 0; c < kCascades; ++c) {
    const float t = static_cast<float>(c + 1) / kCascades;
    const float uniform = frame.near + (frame.far - frame.near) * t;
    const float logarithmic = frame.near * std::pow(frame.far / frame.near, t);
    const float split_far = uniform + (logarithmic - uniform) * kCascadeSplitBlend;
    // The slice's bounding sphere: its size does not change as the camera
    // turns, so texels keep their size and, snapped below, their place.
    glm::vec3 corners[8];
    glm::vec3 centre(0.0f);
    for (int k = 0; k < 8; ++k) {
      const float d = (k & 4) ? split_far : split_near;
      corners[k] = glm::vec3(camera_to_world * glm::vec4((k & 1 ? 1.0f : -1.0f) * d * tan_x, (k & 2 ? 1.0f : -1.0f) * d * tan_y, -d, 1.0f));
      centre += corners[k] / 8.0f;
    }
    float radius = 0.0f;
    for (const glm::vec3& corner : corners) radius = std::max(radius, glm::length(corner - centre));
    radius = std::ceil(radius * 16.0f) / 16.0f;
    const float texel = 2.0f * radius / static_cast<float>(resolution);
    glm::vec3 centre_light = glm::vec3(light_view * glm::vec4(centre, 1.0f));
    centre_light.x = std::floor(centre_light.x / texel) * texel;
    centre_light.y = std::floor(centre_light.y / texel) * texel;
    const float margin = 0.01f * (scene_far - scene_near) + 0.1f;
    // glm's [0, 1] orthographic depth, turned round to the reversed convention (near 1, far 0).
    glm::mat4 reverse(1.0f);
    reverse[2][2] = -1.0f;
    reverse[3][2] = 1.0f;
    const glm::mat4 projection = reverse * glm::orthoRH_ZO(centre_light.x - radius, centre_light.x + radius, centre_light.y - radius,
                                                           centre_light.y + radius, scene_near - margin, scene_far + margin);
    views[static_cast<std::size_t>(c)].view_projection = projection * light_view;
    views[static_cast<std::size_t>(c)].params = glm::vec4(texel, split_far, 0.0f, 0.0f);
    split_near = split_far;
  }
  return views;
}

}  // namespace atrium::shadows
