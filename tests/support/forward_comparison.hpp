// The comparison every technique test makes: a mode against forward in the
// same World from each of the five stored views (PSNR at least 40 dB, and at
// most `allowed_share` of the pixels off by more than 8 levels in a channel).
// Each image is kept as compare_NAME_viewK.png for a look. Targets are
// poisoned (FrameGraph::set_poison): a texel a mode leaves unwritten shows as
// a marker instead of keeping forward's colour from the frame before.
#pragma once

#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "app/cli.hpp"
#include "app/world.hpp"
#include "assets/image.hpp"
#include "support/modes.hpp"

namespace atrium::testing {

// The share of pixels where some colour channel differs by more than `tolerance`.
inline double share_differing(const assets::Image& a, const assets::Image& b, int tolerance) {
  std::size_t differing = 0;
  for (std::size_t i = 0; i + 3 < a.rgba.size(); i += 4) {
    for (std::size_t c = 0; c < 3; ++c) {
      if (std::abs(int(a.rgba[i + c]) - int(b.rgba[i + c])) > tolerance) {
        ++differing;
        break;
      }
    }
  }
  return static_cast<double>(differing) / static_cast<double>(a.rgba.size() / 4);
}

// From each of the world's five stored views (or those in `views`), renders
// forward and then every other mode that runs with the world's options, and calls `check(mode, view, reference,
// image)` with forward's image as the reference.
template <typename Check>
void compare_every_mode_with_forward(World& world, Check check, const std::vector<int>& views = {1, 2, 3, 4, 5}) {
  world.registry().resource<RendererSettings>().poison_targets = true;
  for (const int view : views) {
    world.set_view(view);
    world.set_mode("forward");
    world.frame(0.0);
    const assets::Image reference = world.renderer().read_output();
    for (const std::string& mode : non_forward_modes(world.registry().resource<RendererSettings>().technique_options)) {
      world.set_mode(mode);
      world.frame(0.0);
      check(mode, view, reference, world.renderer().read_output());
    }
  }
}

inline void expect_forward_picture_from_every_view(World& world, const std::string& mode, const std::string& name,
                                                   double allowed_share = 0.0) {
  world.registry().resource<RendererSettings>().poison_targets = true;
  for (int view = 1; view <= 5; ++view) {
    world.set_view(view);
    world.set_mode("forward");
    world.frame(0.0);
    const assets::Image reference = world.renderer().read_output();
    world.set_mode(mode);
    world.frame(0.0);
    const assets::Image image = world.renderer().read_output();
    assets::write_png("compare_" + name + "_view" + std::to_string(view) + ".png", image);
    EXPECT_GE(assets::psnr(reference, image), kMinimumPsnr) << name << " view " << view;
    EXPECT_LE(share_differing(reference, image, 8), allowed_share) << name << " view " << view;
  }
}

}  // namespace atrium::testing
