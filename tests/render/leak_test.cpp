// No leaks across what users repeat: 1000 mode switches, 100 resizes and 10
// scene reloads leave the live GL objects and the estimated GPU memory where
// they were (debug views and G-buffer thumbnails on, so their targets count).
#include "app/world.hpp"
#include "components/frame_resources.hpp"
#include "gfx/gl_object.hpp"
#include "support/gl_test.hpp"
#include "render/techniques/technique.hpp"

namespace atrium {
namespace {

using Leaks = testing::GlTest;

const std::string kTeapot = std::string(ATRIUM_TESTDATA_DIR) + "/gltf/blender-exports/teapot.gltf";

struct Snapshot {
  std::int64_t objects;
  std::uint64_t bytes;
  bool operator==(const Snapshot&) const = default;
};

Snapshot snapshot() { return {gfx::live_gl_objects(), gfx::estimated_gpu_memory_bytes()}; }

std::ostream& operator<<(std::ostream& out, const Snapshot& s) { return out << s.objects << " objects, " << s.bytes << " bytes"; }

TEST_F(Leaks, AThousandModeSwitchesAndAHundredResizesLeaveNothingBehind) {
  World world({.scene = kTeapot, .lights = 48u, .mode = "forward", .size = {48, 27}});
  auto& settings = world.registry().resource<RendererSettings>();
  settings.gbuffer_thumbnails = true;
  const auto modes = techniques::technique_table();
  // One round first: programs (the light-lists view's included) compile and
  // stay cached, as they should.
  for (const auto& info : modes) {
    world.set_mode(std::string(info.name));
    for (const char* view : {"light-lists", "diffuse-light", ""}) {
      settings.debug_view = view;
      world.frame(0.0);
    }
  }
  // The frame graph's pool gives back a transient target three frames after
  // the last frame that used it: forward's frames let it settle.
  auto settle = [&] {
    for (int i = 0; i < 4; ++i) world.frame(0.0);
  };
  auto switch_modes = [&](int switches) {
    for (int i = 0; i < switches; ++i) {
      world.set_mode(std::string(modes[static_cast<std::size_t>(i) % modes.size()].name));
      // The light-sum views turn the split targets on; leaving them drops the targets.
      settings.debug_view = i % 50 == 0 ? "light-lists" : i % 50 == 25 ? "diffuse-light" : "";
      world.frame(0.0);
    }
    settings.debug_view.clear();
    world.set_mode("forward");
  };
  // Framebuffers on the long-lived targets are cached until the targets are
  // made again (the split targets' toggles): 100 switches end as 1000 do, so
  // the same ones are cached when each snapshot is taken. The views'
  // thumbnails are made by the first frame with a technique's G-buffer, and kept.
  switch_modes(100);
  settle();
  const Snapshot before = snapshot();
  EXPECT_GT(before.bytes, 0u);
  switch_modes(1000);
  settle();
  EXPECT_EQ(snapshot(), before) << "after 1000 mode switches";

  world.set_mode("clustered-deferred");
  // The clusters' light lists depend on the pixels they hold, so the global
  // list settles at the largest size a round of resizes needs; after that a
  // second round must leave everything as it was.
  auto resize_round = [&] {
    for (int i = 0; i < 100; ++i) {
      world.set_size({16 + (i % 9) * 8, 9 + (i % 7) * 6});
      world.frame(0.0);
    }
    world.set_size({48, 27});
    settle();
  };
  resize_round();
  const Snapshot clustered = snapshot();
  resize_round();
  EXPECT_EQ(snapshot(), clustered) << "after 100 more resizes";
}

// Shadows: the atlas is made when K turns from 0 and given back at 0; between
// mode switches and K changes its objects and memory stay where they were.
TEST_F(Leaks, AThousandModeSwitchesAndShadowCountChangesLeaveTheAtlasAsItWas) {
  World world({.scene = kTeapot, .lights = 24u, .mode = "forward", .size = {48, 27}});
  auto& settings = world.registry().resource<RendererSettings>();
  const auto modes = techniques::technique_table();
  const int counts[] = {4, 0, 16, 1, 8};
  for (const int count : counts) {
    settings.shadows = count;
    for (const auto& info : modes) {
      world.set_mode(std::string(info.name));
      world.frame(0.0);
    }
  }
  settings.shadows = 4;
  // The frame graph's pool gives back a transient target three frames after
  // the last frame that used it: forward's frames let it settle.
  auto settle = [&] {
    for (int i = 0; i < 4; ++i) world.frame(0.0);
  };
  world.set_mode("forward");
  settle();
  const Snapshot before = snapshot();
  for (int i = 0; i < 1000; ++i) {
    world.set_mode(std::string(modes[static_cast<std::size_t>(i) % modes.size()].name));
    settings.shadows = counts[static_cast<std::size_t>(i / 7) % std::size(counts)];
    world.frame(0.0);
  }
  settings.shadows = 4;
  world.set_mode("forward");
  settle();
  EXPECT_EQ(snapshot(), before) << "after 1000 mode switches and shadow count changes";
}

TEST_F(Leaks, TenSceneReloadsGiveEveryObjectBack) {
  const Snapshot before = snapshot();
  for (int i = 0; i < 10; ++i) {
    World world({.scene = kTeapot, .lights = 16u, .mode = i % 2 ? "tiled-deferred" : "clustered-forward", .size = {48, 27}});
    world.frame(0.0);
    EXPECT_GT(snapshot().bytes, before.bytes);
  }
  EXPECT_EQ(snapshot(), before);
}

}  // namespace
}  // namespace atrium
