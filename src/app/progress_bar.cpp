#include "app/progress_bar.hpp"

#include <unistd.h>

#include <cstdio>

namespace atrium {

ProgressBar::ProgressBar(std::string label)
    : label_(std::move(label)), start_(std::chrono::steady_clock::now()), terminal_(isatty(STDERR_FILENO) == 1) {}

ProgressBar::~ProgressBar() {
  if (shown_) std::fputs("\r\033[K", stderr);
}

void ProgressBar::update(std::string_view stage, std::size_t done, std::size_t total) {
  if (!terminal_) return;
  std::lock_guard lock(mutex_);
  if (!shown_ && std::chrono::steady_clock::now() - start_ < std::chrono::seconds(1)) return;
  shown_ = true;
  constexpr int kWidth = 30;
  const int filled = total ? static_cast<int>(kWidth * done / total) : kWidth;
  std::string bar(static_cast<std::size_t>(filled), '#');
  bar.resize(kWidth, '.');
  std::fprintf(stderr, "\r\033[Kloading %s [%s] %s %zu/%zu", label_.c_str(), bar.c_str(), std::string(stage).c_str(), done, total);
  std::fflush(stderr);
}

}  // namespace atrium
