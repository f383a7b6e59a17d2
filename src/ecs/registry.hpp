// The registry: creates and destroys entities, stores one sparse set per component
// type, hands out views, and keeps per-world singletons ("resources": the frame
// clock, the camera matrices, the renderer's settings) that systems share.
//
// Rules for structural change while a view is iterating (see View::each):
//  * Changing component values is always allowed.
//  * Removing components from, or destroying, the entity being visited is allowed:
//    the walk notices the change and visits the entity that swap-and-pop moved
//    into the freed slot.
//  * Adding components and creating entities is allowed; entities that enter the
//    view during the walk may or may not be visited.
//  * Removing components from, or destroying, *other* entities of the view is not
//    allowed during the walk (an entity could be skipped or visited twice);
//    collect them and apply the change after `each` returns.
//  * A reference or pointer to a component of type T is invalidated by adding a T
//    to any entity (the pool may grow) and by removing any T (the last T moves).
//
// Change detection: every way of reaching a component for writing (add, get,
// try_get on a non-const registry, a view whose callback takes it by non-const
// reference, Lookup<T>) stamps its slot with the change clock, and
// written_since tells a system what was written after it last called
// advance_change_clock: the light buffer skips the lights nothing wrote.
// Keep no component pointer across frames to write through later: such a
// write would go unstamped.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <typeindex>
#include <typeinfo>
#include <unordered_map>
#include <utility>
#include <span>
#include <vector>

#include "ecs/entity.hpp"
#include "ecs/sparse_set.hpp"

namespace atrium::ecs {

namespace detail {
inline std::size_t next_component_id() {
  static std::size_t counter = 0;
  return counter++;
}
template <typename T>
std::size_t component_id() {
  static const std::size_t id = next_component_id();
  return id;
}
}  // namespace detail

template <typename... Ts>
class View;

inline constexpr std::size_t kMaxViewComponents = 8;

// Whether the pools of a multi-component view hold the same entities in the same
// order, remembered for the pools' versions it was computed at.
struct ViewAlignment {
  std::vector<std::uint64_t> versions;
  bool aligned = false;
};

class Registry {
 public:
  Registry() = default;
  Registry(const Registry&) = delete;
  Registry& operator=(const Registry&) = delete;

  Entity create() {
    if (!free_.empty()) {
      const std::uint32_t index = free_.back();
      free_.pop_back();
      return Entity{index, generations_[index]};
    }
    generations_.push_back(0);
    return Entity{static_cast<std::uint32_t>(generations_.size() - 1), 0};
  }

  // Removes every component of e and retires its handle. Destroying a stale or
  // null handle does nothing.
  void destroy(Entity e) {
    if (!alive(e)) return;
    for (auto& pool : pools_) {
      if (pool) pool->remove(e);
    }
    ++generations_[e.index];
    free_.push_back(e.index);
  }

  [[nodiscard]] bool alive(Entity e) const {
    return e.index < generations_.size() && generations_[e.index] == e.generation;
  }
  [[nodiscard]] std::size_t alive_count() const { return generations_.size() - free_.size(); }

  template <typename T, typename... Args>
  T& add(Entity e, Args&&... args) {
    require_alive(e, "add");
    return pool<T>().emplace(e, std::forward<Args>(args)...);
  }

  template <typename T>
  bool remove(Entity e) {
    return alive(e) && pool<T>().remove(e);
  }

  template <typename T>
  [[nodiscard]] bool has(Entity e) const {
    const auto* p = find_pool<T>();
    return alive(e) && p && p->contains(e);
  }

  template <typename T>
  [[nodiscard]] T& get(Entity e) {
    T* component = try_get<T>(e);
    if (!component) {
      require_alive(e, "get");
      throw std::out_of_range(std::string("ecs: entity has no component ") + typeid(T).name());
    }
    return *component;
  }

  template <typename T>
  [[nodiscard]] T* try_get(Entity e) {
    auto* p = find_pool<T>();
    return (alive(e) && p) ? p->try_get(e) : nullptr;
  }
  template <typename T>
  [[nodiscard]] const T* try_get(Entity e) const {
    const auto* p = find_pool<T>();
    return (alive(e) && p) ? p->try_get(e) : nullptr;
  }

  template <typename... Ts>
  [[nodiscard]] View<Ts...> view() {
    ViewAlignment* alignment = nullptr;
    if constexpr (sizeof...(Ts) > 1) alignment = &alignments_[{detail::component_id<Ts>()...}];
    return View<Ts...>(alignment, pool<Ts>()...);
  }

  // The entities holding T and their components, in pool order (index i of
  // one is index i of the other): for walks split over threads, during which
  // nothing may add or remove components (a View allows that, this does not).
  template <typename T>
  [[nodiscard]] std::span<const Entity> entities_with() const {
    const auto* p = find_pool<T>();
    return p ? std::span<const Entity>(p->entities()) : std::span<const Entity>();
  }
  template <typename T>
  [[nodiscard]] std::span<const T> components_of() const {
    const auto* p = find_pool<T>();
    return p ? std::span<const T>(p->components()) : std::span<const T>();
  }
  // try_get for such walks: reads only.
  template <typename T>
  [[nodiscard]] const T* find(Entity e) const {
    const auto* p = find_pool<T>();
    return (alive(e) && p && p->contains(e)) ? &p->get(e) : nullptr;
  }
  // find for such walks, in a tight loop: the pool is looked up once, and
  // each find first tries the slot after the last one found, so entities
  // that were given their components in the same order are found without the
  // sparse array. One per thread. Lookup<const T> (from a const registry)
  // reads; Lookup<T> writes, each thread only its own entities' components.
  template <typename T>
  class Lookup {
    using Pool = std::conditional_t<std::is_const_v<T>, const SparseSet<std::remove_const_t<T>>, SparseSet<T>>;

   public:
    explicit Lookup(Pool* pool) : pool_(pool) {}
    [[nodiscard]] T* find(Entity e) {
      if (!pool_) return nullptr;
      const std::uint32_t slot = pool_->find_slot(e, next_);
      if (slot == SparseSetBase::kAbsent) return nullptr;
      next_ = std::size_t{slot} + 1;
      if constexpr (!std::is_const_v<T>) pool_->mark_written(slot);
      return &pool_->components()[slot];
    }
    // The slot of the component the last find returned.
    [[nodiscard]] std::uint32_t last_slot() const { return static_cast<std::uint32_t>(next_ - 1); }

   private:
    Pool* pool_;
    std::size_t next_ = 0;
  };
  template <typename T>
  [[nodiscard]] Lookup<const T> lookup() const {
    return Lookup<const T>(find_pool<T>());
  }
  template <typename T>
  [[nodiscard]] Lookup<T> lookup() {
    return Lookup<T>(find_pool<T>());
  }

  template <typename T>
  [[nodiscard]] std::size_t count() const {
    const auto* p = find_pool<T>();
    return p ? p->size() : 0;
  }
  // Changes whenever an entity gains or loses a T (0 while none ever had one).
  template <typename T>
  [[nodiscard]] std::uint64_t structure_version() const {
    const auto* p = find_pool<T>();
    return p ? p->version() : 0;
  }

  // Change detection (see the top of this file). A system that wants to know
  // what changed since it last looked keeps what this returns and asks
  // written_since with it next time; writes from now on are past it.
  std::uint64_t advance_change_clock() { return change_clock_.fetch_add(1, std::memory_order_relaxed); }
  // Whether a T in pool slots [first, end) (entities_with<T>()'s order) was
  // reached for writing after the advance_change_clock call that returned `since`.
  template <typename T>
  [[nodiscard]] bool written_since(std::size_t first, std::size_t end, std::uint64_t since) const {
    const auto* p = find_pool<T>();
    return p && p->written_since(first, end, since);
  }

  // Resources: at most one value of each type per registry.
  template <typename T, typename... Args>
  T& set_resource(Args&&... args) {
    auto holder = std::make_shared<T>(std::forward<Args>(args)...);
    T& ref = *holder;
    resources_[std::type_index(typeid(T))] = std::move(holder);
    return ref;
  }
  template <typename T>
  [[nodiscard]] T* try_resource() {
    return const_cast<T*>(std::as_const(*this).try_resource<T>());
  }
  template <typename T>
  [[nodiscard]] const T* try_resource() const {
    auto it = resources_.find(std::type_index(typeid(T)));
    return it == resources_.end() ? nullptr : static_cast<const T*>(it->second.get());
  }
  template <typename T>
  [[nodiscard]] T& resource() {
    return const_cast<T&>(std::as_const(*this).resource<T>());
  }
  template <typename T>
  [[nodiscard]] const T& resource() const {
    const T* r = try_resource<T>();
    if (!r) throw std::out_of_range(std::string("ecs: no resource ") + typeid(T).name());
    return *r;
  }

 private:
  template <typename T>
  SparseSet<T>& pool() {
    const std::size_t id = detail::component_id<T>();
    if (id >= pools_.size()) pools_.resize(id + 1);
    if (!pools_[id]) pools_[id] = std::make_unique<SparseSet<T>>(change_clock_);
    return static_cast<SparseSet<T>&>(*pools_[id]);
  }
  template <typename T>
  const SparseSet<T>* find_pool() const {
    const std::size_t id = detail::component_id<T>();
    return id < pools_.size() ? static_cast<const SparseSet<T>*>(pools_[id].get()) : nullptr;
  }
  template <typename T>
  SparseSet<T>* find_pool() {
    return const_cast<SparseSet<T>*>(std::as_const(*this).find_pool<T>());
  }
  void require_alive(Entity e, const char* what) const {
    if (!alive(e)) {
      throw std::invalid_argument(std::string("ecs: ") + what + " on a stale or null entity (index " +
                                  std::to_string(e.index) + ", generation " +
                                  std::to_string(e.generation) + ")");
    }
  }

  ChangeClock change_clock_{1};
  std::vector<std::uint32_t> generations_;
  std::vector<std::uint32_t> free_;
  std::vector<std::unique_ptr<SparseSetBase>> pools_;
  std::unordered_map<std::type_index, std::shared_ptr<void>> resources_;
  std::map<std::vector<std::size_t>, ViewAlignment> alignments_;
};

// Entities that have every component in Ts. The walk is driven by the smallest of
// the pools, so a view over a rare and a common component costs the rare one.
// When all pools hold the same entities in the same order (components that are
// added together), the walk reads them in lockstep like plain arrays. Each step
// checks the pools' versions, so a structural change made by the callback is
// noticed at once and the walk continues on fresh storage.
template <typename... Ts>
class View {
  static_assert(sizeof...(Ts) >= 1 && sizeof...(Ts) <= kMaxViewComponents, "a view takes 1 to 8 component types");
  using Versions = std::array<std::uint64_t, sizeof...(Ts)>;

 public:
  explicit View(ViewAlignment* alignment, SparseSet<Ts>&... pools) : pools_(&pools...), alignment_(alignment) {
    driver_ = std::get<0>(pools_);
    ((driver_ = pools.size() < driver_->size() ? &pools : driver_), ...);
  }

  // Calls fn(entity, components...) or fn(components...) for every match.
  template <typename Fn>
  void each(Fn&& fn) {
    std::size_t end = driver_->size();
    std::size_t i = 0;
    while (i < end) i = aligned() ? walk_aligned(fn, i, end) : walk_sparse(fn, i, end);
  }

  // Number of entities in the driving pool: an upper bound on the matches.
  [[nodiscard]] std::size_t size_hint() const { return driver_->size(); }

 private:
  [[nodiscard]] Versions versions() const { return {std::get<SparseSet<Ts>*>(pools_)->version()...}; }

  bool aligned() {
    if constexpr (sizeof...(Ts) == 1) {
      return true;
    } else {
      const std::size_t size = driver_->size();
      if (((std::get<SparseSet<Ts>*>(pools_)->size() != size) || ...)) return false;
      const Versions now = versions();
      if (!std::equal(now.begin(), now.end(), alignment_->versions.begin(), alignment_->versions.end())) {
        const auto& reference = driver_->entities();
        alignment_->aligned = ((std::get<SparseSet<Ts>*>(pools_)->entities() == reference) && ...);
        alignment_->versions.assign(now.begin(), now.end());
      }
      return alignment_->aligned;
    }
  }

  // Whether fn could write component I: it takes it by non-const reference
  // (it cannot be called with that one component const). Such components'
  // slots are marked written: a sparse walk marks each as it hands it out,
  // an aligned walk its whole range after its loop.
  template <std::size_t I, std::size_t J, typename T>
  using ConstAt = std::conditional_t<I == J, const T&, T&>;
  template <typename Fn, std::size_t I, std::size_t... J>
  static constexpr bool writes(std::index_sequence<J...>) {
    return !(std::is_invocable_v<Fn&, Entity, ConstAt<I, J, Ts>...> || std::is_invocable_v<Fn&, ConstAt<I, J, Ts>...>);
  }
  template <typename Fn, std::size_t... I>
  static constexpr std::array<bool, sizeof...(Ts)> written_by(std::index_sequence<I...>) {
    return {writes<Fn, I>(std::index_sequence_for<Ts...>{})...};
  }
  template <typename Fn, std::size_t... I>
  void mark_slots(const std::array<std::uint32_t, sizeof...(Ts)>& slots, std::index_sequence<I...>) {
    constexpr std::array<bool, sizeof...(Ts)> written = written_by<Fn>(std::index_sequence_for<Ts...>{});
    ((written[I] ? std::get<I>(pools_)->mark_written(slots[I]) : void()), ...);
  }
  // After an aligned walk of [first, end): a store per run of slots, not one
  // per entity (the walk's loop stays as tight as a plain array's).
  template <typename Fn, std::size_t... I>
  void mark_range(std::size_t first, std::size_t end, std::index_sequence<I...>) {
    constexpr std::array<bool, sizeof...(Ts)> written = written_by<Fn>(std::index_sequence_for<Ts...>{});
    ((written[I] ? std::get<I>(pools_)->mark_written(first, end) : void()), ...);
  }

  template <typename Fn, typename... Cs>
  static void call(Fn& fn, Entity e, Cs&... components) {
    if constexpr (std::is_invocable_v<Fn, Entity, Ts&...>) {
      fn(e, components...);
    } else {
      fn(components...);
    }
  }

  template <std::size_t... I>
  [[nodiscard]] bool changed_since(const Versions& before, std::index_sequence<I...>) const {
    return ((std::get<I>(pools_)->version() != before[I]) || ...);
  }

  // Both walks visit [i, end) and return where the next walk starts: `end`, or
  // the first index to visit after the callback changed the pools. `end` is the
  // count of entities the walk started with that are still unvisited or behind i;
  // entities added during the walk lie past it and are not visited.
  template <typename Fn>
  std::size_t walk_aligned(Fn& fn, std::size_t i, std::size_t& end) {
    const Versions before = versions();
    const Entity* entities = driver_->entities().data();
    const auto data = std::make_tuple(std::get<SparseSet<Ts>*>(pools_)->components().data()...);
    const Entity last_original = entities[end - 1];
    // The slots handed out are marked after the loop (a call before it keeps
    // the compiler from vectorising the loop).
    const std::size_t first = i;
    for (; i < end; ++i) {
      call(fn, entities[i], std::get<Ts*>(data)[i]...);
      if (changed_since(before, std::index_sequence_for<Ts...>{})) [[unlikely]] {
        mark_range<Fn>(first, i + 1, std::index_sequence_for<Ts...>{});
        return next_after_change(i, end, last_original);
      }
    }
    mark_range<Fn>(first, i, std::index_sequence_for<Ts...>{});
    return i;
  }

  template <typename Fn>
  std::size_t walk_sparse(Fn& fn, std::size_t i, std::size_t& end) {
    const Versions before = versions();
    const Entity last_original = driver_->entities()[end - 1];
    for (; i < end; ++i) {
      const Entity e = driver_->entities()[i];
      const std::array<std::uint32_t, sizeof...(Ts)> slots{std::get<SparseSet<Ts>*>(pools_)->find_slot(e, i)...};
      if (std::find(slots.begin(), slots.end(), SparseSetBase::kAbsent) != slots.end()) continue;
      mark_slots<Fn>(slots, std::index_sequence_for<Ts...>{});
      invoke(fn, e, slots, std::index_sequence_for<Ts...>{});
      if (changed_since(before, std::index_sequence_for<Ts...>{})) [[unlikely]] {
        return next_after_change(i, end, last_original);
      }
    }
    return i;
  }

  // After the callback at index i changed the pools: when the last entity the
  // walk started with was moved into slot i (swap-and-pop of the visited one),
  // visit slot i again and shorten the walk by one; otherwise go on from i + 1.
  std::size_t next_after_change(std::size_t i, std::size_t& end, Entity last_original) const {
    const auto& entities = driver_->entities();
    if (i + 1 < end && i < entities.size() && entities[i] == last_original) {
      --end;
      return i;
    }
    end = std::min(end, entities.size());
    return i + 1;
  }

  template <typename Fn, std::size_t... I>
  void invoke(Fn& fn, Entity e, const std::array<std::uint32_t, sizeof...(Ts)>& slots, std::index_sequence<I...>) {
    call(fn, e, std::get<I>(pools_)->components()[slots[I]]...);
  }

  // If the visited entity left the driving pool, swap-and-pop moved an unvisited
  // entity into its slot: visit that slot again.
  [[nodiscard]] std::size_t next_after_change(std::size_t i, Entity visited) const {
    return (i < driver_->size() && driver_->entities()[i] == visited) ? i + 1 : i;
  }

  std::tuple<SparseSet<Ts>*...> pools_;
  ViewAlignment* alignment_ = nullptr;
  SparseSetBase* driver_ = nullptr;
};

}  // namespace atrium::ecs
