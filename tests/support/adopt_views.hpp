// A model's scene drawn from another scene's cameras under its lights: tests
// that compare a file with its source render both from the same views.
#pragma once

#include "assets/scene.hpp"

namespace atrium::testing {

inline void adopt_views_and_lights(assets::SceneDescription& scene, const assets::SceneDescription& like) {
  scene.views = like.views;
  scene.lights = like.lights;
  scene.bounds = like.bounds;
}

}  // namespace atrium::testing
