#include "framework/harness/status_line.hpp"

#include <cstdio>

namespace hystbench {

StatusLine::StatusLine(bool enabled) : enabled_(enabled), start_(std::chrono::steady_clock::now()) {}

void StatusLine::show(const std::string& text) {
  if (!enabled_) return;
  std::lock_guard<std::mutex> lock(mutex_);
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  std::fprintf(stderr, "\r  %s   elapsed %.0f s\033[K", text.c_str(), elapsed);
  std::fflush(stderr);
  shown_ = true;
}

void StatusLine::finish() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (enabled_ && shown_) std::fprintf(stderr, "\n");
  shown_ = false;
}

}  // namespace hystbench
