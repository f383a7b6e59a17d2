// A progress bar on the terminal for loads that take longer than a second.
// Quiet when stderr is not a terminal (logs, CI) and for fast loads.
#pragma once

#include <chrono>
#include <mutex>
#include <string>
#include <string_view>

namespace atrium {

class ProgressBar {
 public:
  explicit ProgressBar(std::string label);
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  void update(std::string_view stage, std::size_t done, std::size_t total);

 private:
  std::string label_;
  std::chrono::steady_clock::time_point start_;
  bool terminal_ = false;
  bool shown_ = false;
  std::mutex mutex_;
};

}  // namespace atrium
