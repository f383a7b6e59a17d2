#include <gtest/gtest.h>

#include <functional>
#include <span>
#include <string>
#include <vector>

#include "ecs/registry.hpp"

namespace atrium::ecs {
namespace {

struct Position {
  float x = 0, y = 0;
};
struct Velocity {
  float dx = 0, dy = 0;
};
struct Name {
  std::string text;
};

TEST(Registry, CreatedEntitiesAreAliveAndDistinct) {
  Registry registry;
  const Entity a = registry.create();
  const Entity b = registry.create();
  EXPECT_NE(a, b);
  EXPECT_TRUE(registry.alive(a));
  EXPECT_TRUE(registry.alive(b));
  EXPECT_EQ(registry.alive_count(), 2u);
  EXPECT_FALSE(registry.alive(kNullEntity));
}

TEST(Registry, StaleHandleIsDetectedAfterSlotReuse) {
  Registry registry;
  const Entity old_handle = registry.create();
  registry.add<Position>(old_handle, 1.0f, 2.0f);
  registry.destroy(old_handle);
  const Entity reused = registry.create();
  ASSERT_EQ(reused.index, old_handle.index) << "the slot is recycled";
  EXPECT_NE(reused.generation, old_handle.generation);
  EXPECT_FALSE(registry.alive(old_handle));
  EXPECT_TRUE(registry.alive(reused));
  // The stale handle never reaches the new entity's components.
  registry.add<Position>(reused, 5.0f, 6.0f);
  EXPECT_FALSE(registry.has<Position>(old_handle));
  EXPECT_EQ(registry.try_get<Position>(old_handle), nullptr);
  EXPECT_THROW(registry.add<Velocity>(old_handle), std::invalid_argument);
  EXPECT_THROW((void)registry.get<Position>(old_handle), std::invalid_argument);
  EXPECT_FALSE(registry.remove<Position>(old_handle));
  EXPECT_TRUE(registry.has<Position>(reused));
  registry.destroy(old_handle);  // destroying a stale handle does nothing
  EXPECT_TRUE(registry.alive(reused));
}

TEST(Registry, AddGetTryGetHasRemove) {
  Registry registry;
  const Entity e = registry.create();
  EXPECT_FALSE(registry.has<Position>(e));
  registry.add<Position>(e, 3.0f, 4.0f);
  ASSERT_TRUE(registry.has<Position>(e));
  EXPECT_FLOAT_EQ(registry.get<Position>(e).y, 4.0f);
  registry.get<Position>(e).x = 7.0f;
  EXPECT_FLOAT_EQ(registry.try_get<Position>(e)->x, 7.0f);
  EXPECT_EQ(registry.try_get<Velocity>(e), nullptr);
  EXPECT_THROW((void)registry.get<Velocity>(e), std::out_of_range);
  registry.add<Position>(e, 9.0f, 9.0f);  // adding again replaces
  EXPECT_EQ(registry.count<Position>(), 1u);
  EXPECT_FLOAT_EQ(registry.get<Position>(e).x, 9.0f);
  EXPECT_TRUE(registry.remove<Position>(e));
  EXPECT_FALSE(registry.has<Position>(e));
  EXPECT_FALSE(registry.remove<Position>(e));
}

TEST(Registry, RemovalKeepsOtherEntitiesComponents) {
  Registry registry;
  std::vector<Entity> entities;
  for (int i = 0; i < 10; ++i) {
    entities.push_back(registry.create());
    registry.add<Name>(entities.back(), "e" + std::to_string(i));
  }
  registry.remove<Name>(entities[0]);  // swap-and-pop moves the last one into slot 0
  registry.destroy(entities[4]);
  for (int i = 0; i < 10; ++i) {
    if (i == 0 || i == 4) continue;
    EXPECT_EQ(registry.get<Name>(entities[static_cast<std::size_t>(i)]).text, "e" + std::to_string(i));
  }
  EXPECT_EQ(registry.count<Name>(), 8u);
}

TEST(Registry, DestroyRemovesEveryComponent) {
  Registry registry;
  const Entity e = registry.create();
  registry.add<Position>(e);
  registry.add<Velocity>(e);
  registry.destroy(e);
  EXPECT_EQ(registry.count<Position>(), 0u);
  EXPECT_EQ(registry.count<Velocity>(), 0u);
  EXPECT_EQ(registry.alive_count(), 0u);
}

// The pool as two parallel arrays, and a read-only lookup: what walks split
// over threads use (the light buffer's gather).
TEST(Registry, PoolsReadAsParallelArraysForThreadedWalks) {
  Registry registry;
  const Entity a = registry.create(), b = registry.create(), c = registry.create();
  registry.add<Position>(a, 1.0f, 2.0f);
  registry.add<Position>(c, 3.0f, 4.0f);
  registry.add<Velocity>(c, 5.0f, 6.0f);
  const Registry& read = registry;
  const std::span<const Entity> entities = read.entities_with<Position>();
  const std::span<const Position> positions = read.components_of<Position>();
  ASSERT_EQ(entities.size(), 2u);
  ASSERT_EQ(positions.size(), 2u);
  for (std::size_t i = 0; i < entities.size(); ++i) EXPECT_EQ(positions[i].x, registry.get<Position>(entities[i]).x);
  EXPECT_EQ(read.find<Velocity>(a), nullptr);
  ASSERT_NE(read.find<Velocity>(c), nullptr);
  EXPECT_EQ(read.find<Velocity>(c)->dy, 6.0f);
  EXPECT_TRUE(read.entities_with<Name>().empty()) << "no pool yet: empty, not a crash";
  registry.destroy(c);
  EXPECT_EQ(read.find<Velocity>(c), nullptr) << "a stale handle finds nothing";
  (void)b;
}

TEST(Registry, LookupFindsAWalksComponentsInAnyOrder) {
  Registry registry;
  std::vector<Entity> entities;
  for (int i = 0; i < 6; ++i) entities.push_back(registry.create());
  // Velocity's pool holds every other entity, in another order than Position's.
  for (int i = 0; i < 6; ++i) registry.add<Position>(entities[i], static_cast<float>(i), 0.0f);
  for (const int i : {4, 0, 2}) registry.add<Velocity>(entities[i], static_cast<float>(10 * i), 0.0f);
  const Registry& read = registry;
  Registry::Lookup<const Velocity> velocities = read.lookup<Velocity>();
  for (const Entity e : read.entities_with<Position>()) {
    const Velocity* v = velocities.find(e);
    const Velocity* expected = read.find<Velocity>(e);
    ASSERT_EQ(v == nullptr, expected == nullptr);
    if (v) EXPECT_EQ(v->dx, expected->dx);
  }
  Registry::Lookup<const Name> names = read.lookup<Name>();
  EXPECT_EQ(names.find(entities[0]), nullptr) << "no pool yet: nothing found, not a crash";
}

// Change detection: each way of reaching a component for writing marks it, so
// that a system asking written_since sees it; reads mark nothing, and a
// write marks only its own run of slots.
TEST(RegistryChanges, EveryWayToWriteAComponentMarksItAndReadsDoNot) {
  Registry registry;
  constexpr std::size_t kCount = 10 * SparseSetBase::kSlotsPerStamp;
  std::vector<Entity> entities;
  for (std::size_t i = 0; i < kCount; ++i) {
    entities.push_back(registry.create());
    registry.add<Position>(entities.back(), static_cast<float>(i), 0.0f);
    registry.add<Velocity>(entities.back());
  }
  auto slot = [](std::size_t i) { return i; };  // added in order: slot i is entity i
  auto changed = [&](std::uint64_t since) {
    std::vector<std::size_t> runs;
    for (std::size_t run = 0; run * SparseSetBase::kSlotsPerStamp < kCount; ++run) {
      if (registry.written_since<Position>(run * SparseSetBase::kSlotsPerStamp, (run + 1) * SparseSetBase::kSlotsPerStamp, since))
        runs.push_back(run);
    }
    return runs;
  };
  const std::size_t run = SparseSetBase::kSlotsPerStamp;
  std::uint64_t since = registry.advance_change_clock();
  EXPECT_TRUE(changed(since).empty()) << "nothing written since the clock moved";

  // Reads: const lookups, find, components_of, a const try_get, a view whose callback takes it const.
  const Registry& read = registry;
  Registry::Lookup<const Position> positions = read.lookup<Position>();
  float sum = positions.find(entities[5])->x + read.find<Position>(entities[run])->x + read.components_of<Position>()[2 * run].x;
  sum += read.try_get<Position>(entities[3 * run])->x;
  registry.view<Position, Velocity>().each([&](const Position& p, Velocity& v) { v.dx = p.x; });
  EXPECT_GT(sum, 0.0f);
  EXPECT_TRUE(changed(since).empty()) << "reads mark nothing";
  EXPECT_TRUE(registry.written_since<Velocity>(0, kCount, since)) << "the view wrote the velocities";

  struct Write {
    const char* how;
    std::function<void()> write;
    std::size_t run;
  };
  const std::vector<Write> writes = {
      {"get", [&] { registry.get<Position>(entities[slot(0)]).x = -1.0f; }, 0},
      {"try_get", [&] { registry.try_get<Position>(entities[slot(run + 1)])->y = 2.0f; }, 1},
      {"add over a component", [&] { registry.add<Position>(entities[slot(2 * run)], 5.0f, 5.0f); }, 2},
      {"a view's non-const parameter", [&] {
         registry.view<Position, Velocity>().each([&](Entity e, Position& p, const Velocity&) {
           if (e == entities[3 * run + 7]) p.y = 1.0f;
         });
       }, 3},
      {"Lookup<T>", [&] { registry.lookup<Position>().find(entities[4 * run + 9])->x = 0.5f; }, 4},
  };
  for (const Write& w : writes) {
    since = registry.advance_change_clock();
    w.write();
    if (std::string(w.how) == "a view's non-const parameter") {
      // A view marks every entity it hands out for writing, written or not.
      EXPECT_EQ(changed(since).size(), kCount / run) << w.how;
    } else {
      EXPECT_EQ(changed(since), std::vector<std::size_t>{w.run}) << w.how;
    }
    EXPECT_FALSE(registry.written_since<Velocity>(0, kCount, since)) << w.how << " marks only the pool it wrote";
    EXPECT_TRUE(changed(registry.advance_change_clock()).empty()) << w.how << ": seen once, then not again";
  }
  // Removing an entity moves the pool's last into its slot: that slot counts as written.
  since = registry.advance_change_clock();
  const std::uint64_t structure = registry.structure_version<Position>();
  registry.remove<Position>(entities[slot(6 * run)]);
  EXPECT_NE(registry.structure_version<Position>(), structure);
  EXPECT_EQ(changed(since), std::vector<std::size_t>{6});
}

TEST(Registry, ResourcesAreSingletonsPerType) {
  Registry registry;
  EXPECT_EQ(registry.try_resource<Position>(), nullptr);
  EXPECT_THROW((void)registry.resource<Position>(), std::out_of_range);
  registry.set_resource<Position>(Position{1, 2});
  registry.resource<Position>().x = 5;
  EXPECT_FLOAT_EQ(registry.resource<Position>().x, 5);
  registry.set_resource<Position>(Position{8, 9});  // replaces
  EXPECT_FLOAT_EQ(registry.resource<Position>().x, 8);
}

}  // namespace
}  // namespace atrium::ecs
