// One sparse set per component type: a sparse array maps an entity's index to a
// slot in two packed arrays (entities and components), so iteration walks dense
// memory and add/remove/lookup are O(1). Removal swaps the last element into the
// hole, which is why views iterate from the back (see registry.hpp).
#pragma once

#include <cassert>
#include <cstdint>
#include <utility>
#include <vector>

#include "ecs/entity.hpp"

namespace atrium::ecs {

// Type-erased base so that the registry can remove an entity from every pool.
class SparseSetBase {
 public:
  virtual ~SparseSetBase() = default;

  [[nodiscard]] bool contains(Entity e) const {
    return e.index < sparse_.size() && sparse_[e.index] != kAbsent &&
           dense_[sparse_[e.index]] == e;
  }
  [[nodiscard]] std::size_t size() const { return dense_.size(); }

  // e's slot in the packed arrays, or kAbsent. `hint` is checked first: when
  // pools hold the same entities in the same order (components added together),
  // a view finds every slot without touching the sparse arrays.
  [[nodiscard]] std::uint32_t find_slot(Entity e, std::size_t hint) const {
    if (hint < dense_.size() && dense_[hint] == e) return static_cast<std::uint32_t>(hint);
    return contains(e) ? sparse_[e.index] : kAbsent;
  }
  static constexpr std::uint32_t kAbsent = 0xffffffffu;
  [[nodiscard]] const std::vector<Entity>& entities() const { return dense_; }
  // Changes whenever an entity joins or leaves the set; never repeats across sets.
  [[nodiscard]] std::uint64_t version() const { return version_; }

  // Removes e's component if it has one; returns whether it did.
  bool remove(Entity e) {
    if (!contains(e)) return false;
    const std::uint32_t slot = sparse_[e.index];
    const std::uint32_t last = static_cast<std::uint32_t>(dense_.size() - 1);
    if (slot != last) {
      dense_[slot] = dense_[last];
      sparse_[dense_[slot].index] = slot;
      move_component(last, slot);
    }
    dense_.pop_back();
    pop_component();
    sparse_[e.index] = kAbsent;
    bump_version();
    return true;
  }

 protected:
  [[nodiscard]] std::uint32_t slot_of(Entity e) const { return sparse_[e.index]; }

  std::uint32_t push_entity(Entity e) {
    if (e.index >= sparse_.size()) sparse_.resize(static_cast<std::size_t>(e.index) + 1, kAbsent);
    const auto slot = static_cast<std::uint32_t>(dense_.size());
    sparse_[e.index] = slot;
    dense_.push_back(e);
    bump_version();
    return slot;
  }

  virtual void move_component(std::uint32_t from, std::uint32_t to) = 0;
  virtual void pop_component() = 0;

 private:
  void bump_version() {
    static std::uint64_t counter = 0;
    version_ = ++counter;
  }

  std::vector<std::uint32_t> sparse_;
  std::vector<Entity> dense_;
  std::uint64_t version_ = 0;
};

template <typename T>
class SparseSet final : public SparseSetBase {
 public:
  // Adds T to e, or replaces the component e already has.
  template <typename... Args>
  T& emplace(Entity e, Args&&... args) {
    if (contains(e)) {
      T& existing = components_[slot_of(e)];
      existing = T{std::forward<Args>(args)...};
      return existing;
    }
    push_entity(e);
    components_.push_back(T{std::forward<Args>(args)...});
    return components_.back();
  }

  [[nodiscard]] T& get(Entity e) {
    assert(contains(e));
    return components_[slot_of(e)];
  }
  [[nodiscard]] const T& get(Entity e) const {
    assert(contains(e));
    return components_[slot_of(e)];
  }
  [[nodiscard]] T* try_get(Entity e) { return contains(e) ? &components_[slot_of(e)] : nullptr; }

  [[nodiscard]] std::vector<T>& components() { return components_; }
  [[nodiscard]] const std::vector<T>& components() const { return components_; }
  [[nodiscard]] T& at_slot(std::uint32_t slot) { return components_[slot]; }

 private:
  void move_component(std::uint32_t from, std::uint32_t to) override {
    components_[to] = std::move(components_[from]);
  }
  void pop_component() override { components_.pop_back(); }

  std::vector<T> components_;
};

}  // namespace atrium::ecs
