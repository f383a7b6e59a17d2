// Draws every debug view each mode offers in `world` (what a tier cannot
// draw, it must not offer), failing the test for any that throws.
#pragma once

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/world.hpp"
#include "components/frame_resources.hpp"
#include "render/techniques/technique.hpp"

namespace atrium::testing {

inline void expect_every_offered_view_draws(World& world) {
  for (const std::string& mode : world.modes()) {
    world.set_mode(mode);
    world.registry().resource<RendererSettings>().debug_view = "";
    world.frame(0.0);
    const std::vector<render::OfferedView> views = world.renderer().offered_views();  // drawing changes them
    EXPECT_GT(views.size(), 2u) << mode;
    for (const render::OfferedView& view : views) {
      world.registry().resource<RendererSettings>().debug_view = view.name;
      EXPECT_NO_THROW(world.frame(0.0)) << mode << ", view " << view.name;
    }
  }
}

}  // namespace atrium::testing
