// One sparse set per component type: a sparse array maps an entity's index to a
// slot in two packed arrays (entities and components), so iteration walks dense
// memory and add/remove/lookup are O(1). Removal swaps the last element into the
// hole, which is why views iterate from the back (see registry.hpp).
// Each run of kSlotsPerStamp slots keeps the change clock's value (the
// registry's) when a component there was last handed out for writing, so that
// a system can skip what nothing wrote since it last looked (written_since).
#pragma once

#include <algorithm>
#include <atomic>
#include <cassert>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "ecs/entity.hpp"

namespace atrium::ecs {

// The registry's count of the times a system looked for changes; every write
// is stamped with its value then. Atomic: systems split over threads write
// components (and so stamps) of one pool at once.
using ChangeClock = std::atomic<std::uint64_t>;

// Type-erased base so that the registry can remove an entity from every pool.
class SparseSetBase {
 public:
  explicit SparseSetBase(const ChangeClock& clock) : clock_(&clock) {}
  virtual ~SparseSetBase() = default;
  static constexpr std::size_t kSlotsPerStamp = 64;

  // Notes that the component in `slot` is being written (or may be: it was
  // handed out for writing). Threads may mark slots of one pool at once.
  void mark_written(std::uint32_t slot) {
    stamps_[slot / kSlotsPerStamp].store(clock_->load(std::memory_order_relaxed), std::memory_order_relaxed);
  }
  // mark_written for every slot in [first, end), a store per run of slots.
  // Out of line: called once per walk, it would otherwise grow every view's
  // walk past what the compiler inlines.
  [[gnu::noinline]] void mark_written(std::size_t first, std::size_t end) {
    const std::uint64_t now = clock_->load(std::memory_order_relaxed);
    end = std::min(end, dense_.size());  // a walk may have shrunk the pool
    for (std::size_t stamp = first / kSlotsPerStamp; first < end && stamp <= (end - 1) / kSlotsPerStamp; ++stamp) {
      stamps_[stamp].store(now, std::memory_order_relaxed);
    }
  }
  // Whether a component in slots [first, end) was marked written while the
  // clock was past `since`, a value Registry::advance_change_clock returned.
  [[nodiscard]] bool written_since(std::size_t first, std::size_t end, std::uint64_t since) const {
    end = std::min(end, dense_.size());
    for (std::size_t stamp = first / kSlotsPerStamp; first < end && stamp <= (end - 1) / kSlotsPerStamp; ++stamp) {
      if (stamps_[stamp].load(std::memory_order_relaxed) > since) return true;
    }
    return false;
  }

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
      mark_written(slot);
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
    grow_stamps(dense_.size() / kSlotsPerStamp + 1);
    mark_written(slot);
    bump_version();
    return slot;
  }

  virtual void move_component(std::uint32_t from, std::uint32_t to) = 0;
  virtual void pop_component() = 0;

 private:
  // Atomics do not move, so the stamps grow by hand (only as entities join:
  // never during a walk over threads).
  void grow_stamps(std::size_t needed) {
    if (needed <= stamp_count_) return;
    const std::size_t count = std::max(needed, stamp_count_ * 2);
    auto grown = std::make_unique<std::atomic<std::uint64_t>[]>(count);
    for (std::size_t i = 0; i < stamp_count_; ++i) grown[i].store(stamps_[i].load(std::memory_order_relaxed), std::memory_order_relaxed);
    stamps_ = std::move(grown);
    stamp_count_ = count;
  }

  void bump_version() {
    static std::uint64_t counter = 0;
    version_ = ++counter;
  }

  std::vector<std::uint32_t> sparse_;
  std::vector<Entity> dense_;
  std::unique_ptr<std::atomic<std::uint64_t>[]> stamps_;  // per run of kSlotsPerStamp slots
  std::size_t stamp_count_ = 0;
  const ChangeClock* clock_;
  std::uint64_t version_ = 0;
};

// Whatever hands out a T& (emplace, get, try_get, at_slot) marks the slot
// written; const access and components() do not (a View or Lookup that writes
// through components() marks the slots itself).
template <typename T>
class SparseSet final : public SparseSetBase {
 public:
  using SparseSetBase::SparseSetBase;

  // Adds T to e, or replaces the component e already has.
  template <typename... Args>
  T& emplace(Entity e, Args&&... args) {
    if (contains(e)) {
      const std::uint32_t slot = slot_of(e);
      mark_written(slot);
      T& existing = components_[slot];
      existing = T{std::forward<Args>(args)...};
      return existing;
    }
    push_entity(e);
    components_.push_back(T{std::forward<Args>(args)...});
    return components_.back();
  }

  [[nodiscard]] T& get(Entity e) {
    assert(contains(e));
    return at_slot(slot_of(e));
  }
  [[nodiscard]] const T& get(Entity e) const {
    assert(contains(e));
    return components_[slot_of(e)];
  }
  [[nodiscard]] T* try_get(Entity e) { return contains(e) ? &at_slot(slot_of(e)) : nullptr; }
  [[nodiscard]] const T* try_get(Entity e) const { return contains(e) ? &components_[slot_of(e)] : nullptr; }

  [[nodiscard]] std::vector<T>& components() { return components_; }
  [[nodiscard]] const std::vector<T>& components() const { return components_; }
  [[nodiscard]] T& at_slot(std::uint32_t slot) {
    mark_written(slot);
    return components_[slot];
  }

 private:
  void move_component(std::uint32_t from, std::uint32_t to) override {
    components_[to] = std::move(components_[from]);
  }
  void pop_component() override { components_.pop_back(); }

  std::vector<T> components_;
};

}  // namespace atrium::ecs
