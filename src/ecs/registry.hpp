// The registry: creates and destroys entities, stores one sparse set per component
// type, hands out views, and keeps per-world singletons ("resources": the frame
// clock, the camera matrices, the renderer's settings) that systems share.
//
// Rules for structural change while a view is iterating (see View::each):
//  * Changing component values is always allowed.
//  * Removing components from, or destroying, the entity being visited is allowed:
//    views walk their smallest pool from the back, so the swap-and-pop of a removal
//    only moves elements that were already visited.
//  * Adding components and creating entities is allowed; entities that enter the
//    view during the walk may or may not be visited. A reference to a component of
//    type T is invalidated by adding a T to any entity (the pool may grow).
//  * Removing components from, or destroying, *other* entities of the view is not
//    allowed during the walk (an element could be skipped); collect them and apply
//    the change after `each` returns.
#pragma once

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <typeindex>
#include <typeinfo>
#include <unordered_map>
#include <utility>
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

  template <typename... Ts>
  [[nodiscard]] View<Ts...> view() {
    return View<Ts...>(pool<Ts>()...);
  }

  template <typename T>
  [[nodiscard]] std::size_t count() const {
    const auto* p = find_pool<T>();
    return p ? p->size() : 0;
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
    if (!pools_[id]) pools_[id] = std::make_unique<SparseSet<T>>();
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

  std::vector<std::uint32_t> generations_;
  std::vector<std::uint32_t> free_;
  std::vector<std::unique_ptr<SparseSetBase>> pools_;
  std::unordered_map<std::type_index, std::shared_ptr<void>> resources_;
};

// Entities that have every component in Ts. The walk is driven by the smallest of
// the pools, so a view over a rare and a common component costs the rare one.
template <typename... Ts>
class View {
 public:
  explicit View(SparseSet<Ts>&... pools) : pools_(&pools...) {
    driver_ = std::get<0>(pools_);
    ((driver_ = pools.size() < driver_->size() ? &pools : driver_), ...);
  }

  // Calls fn(entity, components...) or fn(components...) for every match.
  template <typename Fn>
  void each(Fn&& fn) {
    for (std::size_t i = driver_->size(); i-- > 0;) {
      if (i >= driver_->size()) continue;  // the callback removed more than the current element
      const Entity e = driver_->entities()[i];
      if (!(std::get<SparseSet<Ts>*>(pools_)->contains(e) && ...)) continue;
      if constexpr (std::is_invocable_v<Fn, Entity, Ts&...>) {
        fn(e, std::get<SparseSet<Ts>*>(pools_)->get(e)...);
      } else {
        fn(std::get<SparseSet<Ts>*>(pools_)->get(e)...);
      }
    }
  }

  // Number of entities in the driving pool: an upper bound on the matches.
  [[nodiscard]] std::size_t size_hint() const { return driver_->size(); }

 private:
  std::tuple<SparseSet<Ts>*...> pools_;
  SparseSetBase* driver_ = nullptr;
};

}  // namespace atrium::ecs
