#include <algorithm>
#include <set>

#include <gtest/gtest.h>

#include "ecs/registry.hpp"

namespace atrium::ecs {
namespace {

struct A {
  int value = 0;
};
struct B {
  int value = 0;
};
struct C {
  int value = 0;
};

std::set<std::uint32_t> visited_indices(View<A, B> view) {
  std::set<std::uint32_t> out;
  view.each([&](Entity e, A&, B&) { out.insert(e.index); });
  return out;
}

TEST(View, SingleComponentVisitsEveryOwner) {
  Registry registry;
  int sum = 0;
  for (int i = 0; i < 5; ++i) registry.add<A>(registry.create(), i);
  registry.view<A>().each([&](A& a) { sum += a.value; });
  EXPECT_EQ(sum, 0 + 1 + 2 + 3 + 4);
}

TEST(View, SeveralComponentsVisitOnlyTheIntersection) {
  Registry registry;
  std::set<std::uint32_t> expected;
  for (int i = 0; i < 20; ++i) {
    const Entity e = registry.create();
    if (i % 2 == 0) registry.add<A>(e, i);
    if (i % 3 == 0) registry.add<B>(e, i);
    if (i % 2 == 0 && i % 3 == 0) expected.insert(e.index);
  }
  EXPECT_EQ(visited_indices(registry.view<A, B>()), expected);
  int triple = 0;
  registry.view<A, B, C>().each([&](A&, B&, C&) { ++triple; });
  EXPECT_EQ(triple, 0);
}

TEST(View, IteratesTheSmallestPool) {
  Registry registry;
  for (int i = 0; i < 1000; ++i) registry.add<A>(registry.create(), i);
  const Entity rare = registry.create();
  registry.add<A>(rare);
  registry.add<B>(rare, 42);
  EXPECT_EQ((registry.view<A, B>().size_hint()), 1u);
  EXPECT_EQ((registry.view<B, A>().size_hint()), 1u);
  int calls = 0;
  registry.view<A, B>().each([&](Entity e, A&, B& b) {
    EXPECT_EQ(e, rare);
    EXPECT_EQ(b.value, 42);
    ++calls;
  });
  EXPECT_EQ(calls, 1);
}

TEST(View, ComponentsAreWritableThroughTheView) {
  Registry registry;
  const Entity e = registry.create();
  registry.add<A>(e, 1);
  registry.add<B>(e, 2);
  registry.view<A, B>().each([](A& a, B& b) { a.value += b.value; });
  EXPECT_EQ(registry.get<A>(e).value, 3);
}

TEST(View, RemovingTheCurrentEntitysComponentDuringIterationVisitsEachOnce) {
  Registry registry;
  std::vector<Entity> entities;
  for (int i = 0; i < 50; ++i) {
    entities.push_back(registry.create());
    registry.add<A>(entities.back(), i);
    registry.add<B>(entities.back(), i);
  }
  std::multiset<int> seen;
  registry.view<A, B>().each([&](Entity e, A& a, B&) {
    seen.insert(a.value);
    if (a.value % 2 == 0) registry.remove<A>(e);
  });
  EXPECT_EQ(seen.size(), 50u);
  for (int i = 0; i < 50; ++i) EXPECT_EQ(seen.count(i), 1u) << i;
  EXPECT_EQ(registry.count<A>(), 25u);
}

TEST(View, DestroyingTheCurrentEntityDuringIterationIsSafe) {
  Registry registry;
  for (int i = 0; i < 30; ++i) registry.add<A>(registry.create(), i);
  int visits = 0;
  registry.view<A>().each([&](Entity e, A&) {
    ++visits;
    registry.destroy(e);
  });
  EXPECT_EQ(visits, 30);
  EXPECT_EQ(registry.count<A>(), 0u);
  EXPECT_EQ(registry.alive_count(), 0u);
}

TEST(View, AddingComponentsDuringIterationDoesNotRevisit) {
  Registry registry;
  for (int i = 0; i < 10; ++i) registry.add<A>(registry.create(), i);
  int visits = 0;
  registry.view<A>().each([&](Entity, A&) {
    ++visits;
    registry.add<A>(registry.create(), 100);  // joins the pool behind the walk
  });
  EXPECT_EQ(visits, 10);
  EXPECT_EQ(registry.count<A>(), 20u);
}

TEST(View, DestroyAndRespawnDuringIterationTerminatesAndVisitsEveryOriginal) {
  Registry registry;
  for (int i = 0; i < 20; ++i) {
    const Entity e = registry.create();
    registry.add<A>(e, i);
    registry.add<B>(e, i);
  }
  std::multiset<int> seen;
  registry.view<A, B>().each([&](Entity e, A& a, B&) {
    seen.insert(a.value);
    const int value = a.value;
    registry.destroy(e);
    const Entity replacement = registry.create();
    registry.add<A>(replacement, value + 1000);
    registry.add<B>(replacement, value + 1000);
  });
  for (int i = 0; i < 20; ++i) EXPECT_EQ(seen.count(i), 1u) << i;
  EXPECT_EQ(registry.count<A>(), 20u);
}

TEST(View, RemovalIsSafeWhenPoolsAreNotInTheSameOrder) {
  Registry registry;
  std::vector<Entity> entities;
  for (int i = 0; i < 40; ++i) entities.push_back(registry.create());
  for (int i = 0; i < 40; ++i) registry.add<A>(entities[static_cast<std::size_t>(i)], i);
  for (int i = 39; i >= 0; --i) registry.add<B>(entities[static_cast<std::size_t>(i)], i);  // reversed order
  std::multiset<int> seen;
  registry.view<A, B>().each([&](Entity e, A& a, B& b) {
    EXPECT_EQ(a.value, b.value);
    seen.insert(a.value);
    if (a.value % 3 == 0) registry.remove<B>(e);
    if (a.value % 5 == 0) registry.destroy(e);
  });
  for (int i = 0; i < 40; ++i) EXPECT_EQ(seen.count(i), 1u) << i;
}

}  // namespace
}  // namespace atrium::ecs
