// One radius for every light, set live (the overlay's slider) or at spawn
// (--light-radius): the same lights, the same picture; the radius sets the
// brightness with the reach; directional lights keep theirs.
#include "systems/light_radius.hpp"

#include <gtest/gtest.h>

#include "app/world.hpp"
#include "assets/image.hpp"
#include "components/light.hpp"
#include "support/gl_test.hpp"

namespace atrium {
namespace {

using LightRadiusTest = testing::GlTest;

using testing::kSize;

assets::Image render(World& world) {
  world.frame(0.0);
  return world.renderer().read_output();
}

TEST_F(LightRadiusTest, SettingARadiusLiveDrawsWhatSpawningWithItDraws) {
  std::vector<assets::Image> live_images;
  for (const float radius : {2.0f, 8.0f}) {
    WorldOptions spawned_options{.scene = "atrium", .lights = 64u, .mode = "clustered-deferred", .size = kSize};
    spawned_options.light_radius = radius;
    World spawned(spawned_options);
    World live({.scene = "atrium", .lights = 64u, .mode = "clustered-deferred", .size = kSize});
    set_every_light_radius(live.registry(), radius);
    const assets::Image expected = render(spawned);
    live_images.push_back(render(live));
    EXPECT_EQ(assets::max_channel_difference(expected, live_images.back()), 0) << radius << " m";
  }
  EXPECT_LT(assets::psnr(live_images[0], live_images[1]), 30.0) << "a longer reach is a brighter light";
}

TEST_F(LightRadiusTest, DirectionalLightsKeepTheirIntensityAndHaveNoRadius) {
  World world({.scene = "atrium", .lights = 8u, .mode = "forward", .size = kSize});
  auto& registry = world.registry();
  const ecs::Entity sun = registry.create();
  registry.add<LightColor>(sun, glm::vec3(1.0f), 0.7f);
  registry.add<DirectionalLight>(sun);
  set_every_light_radius(registry, 3.0f);
  EXPECT_FLOAT_EQ(registry.get<LightColor>(sun).intensity, 0.7f);
  EXPECT_FALSE(registry.has<LightRadius>(sun));
  std::size_t points = 0;
  registry.view<LightColor, LightRadius>().each([&](const LightColor&, const LightRadius& r) {
    EXPECT_FLOAT_EQ(r.radius, 3.0f);
    ++points;
  });
  EXPECT_EQ(points, 8u);
}

}  // namespace
}  // namespace atrium
