#pragma once
// One self-rewriting status line on stderr for long single jobs (a fit, a
// diagnosis): what is being done and the elapsed time. Silent when stderr is
// not a terminal, so logs and CI output stay clean. Safe to call from
// several threads.
#include <chrono>
#include <mutex>
#include <string>

namespace hystbench {

class StatusLine {
 public:
  explicit StatusLine(bool enabled);
  void show(const std::string& text);
  // Ends the line (if anything was shown).
  void finish();

 private:
  bool enabled_;
  bool shown_ = false;
  std::mutex mutex_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace hystbench
