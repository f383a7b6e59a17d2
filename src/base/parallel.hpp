// Splitting CPU work over the machine's cores. The WebAssembly build has no
// threads (it runs on the page's one), so there the work runs in turn on the
// caller and the core count is 1.
#pragma once

#include <algorithm>
#include <cstddef>
#include <thread>
#include <vector>

namespace atrium {

#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
inline constexpr bool kHasThreads = false;
#else
inline constexpr bool kHasThreads = true;
#endif

// The threads CPU work may split over: the machine's cores, at least 1.
[[nodiscard]] inline unsigned hardware_threads() { return kHasThreads ? std::max(1u, std::thread::hardware_concurrency()) : 1u; }

// Into how many runs `items` split: one per `items_per_thread` (fewer items
// would not pay for a thread's start), at least 1, at most `threads`.
[[nodiscard]] inline std::size_t share_count(std::size_t items, std::size_t items_per_thread, std::size_t threads = hardware_threads()) {
  return std::clamp<std::size_t>(items / items_per_thread, 1, std::max<std::size_t>(threads, 1));
}

// Items [begin, end) of run `share` of `shares`, in order, even to one item.
struct ShareRange {
  std::size_t begin = 0, end = 0;
};
[[nodiscard]] inline ShareRange share_range(std::size_t items, std::size_t shares, std::size_t share) {
  return {items * share / shares, items * (share + 1) / shares};
}

// Runs work(0) .. work(count - 1), each but the first on a thread of its own
// and the first on the caller, and returns once all are done.
template <typename Work>
void run_in_parallel(std::size_t count, const Work& work) {
  if constexpr (!kHasThreads) {
    for (std::size_t i = 0; i < count; ++i) work(i);
  } else {
    std::vector<std::thread> workers;
    for (std::size_t i = 1; i < count; ++i) workers.emplace_back([&work, i] { work(i); });
    if (count > 0) work(0);
    for (std::thread& worker : workers) worker.join();
  }
}

}  // namespace atrium
