// Loading progress: importers report (stage, done, total) as they go; callers
// decide how to show it. Calls may come from worker threads, one at a time.
#pragma once

#include <cstddef>
#include <functional>
#include <string_view>

namespace atrium::assets {

using ProgressCallback = std::function<void(std::string_view stage, std::size_t done, std::size_t total)>;

}  // namespace atrium::assets
