#pragma once
// Ctrl-C (SIGINT) or SIGTERM during a run. Every finished trial is already
// on disk when it is reported, so stopping needs no cooperation from the
// running trials: they are abandoned, the process prints how to resume and
// exits with 128 + the signal number (130 for Ctrl-C).
//
// The signals are blocked in the constructing thread (and so in every
// thread it starts later, OpenMP's included) and taken by one watcher
// thread, which never acts while a trial is being written: it takes
// `mutex()` first, so a Ctrl-C cannot tear a line of trials.jsonl.
#include <functional>
#include <mutex>
#include <signal.h>
#include <string>
#include <thread>

namespace hystbench::cli {

class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  // What to print when interrupted (called under mutex()).
  void set_message(std::function<std::string()> message);
  // Hold while writing a finished trial.
  std::mutex& mutex() { return mutex_; }

 private:
  void watch();

  std::mutex mutex_;
  std::function<std::string()> message_;
  sigset_t signals_{};
  sigset_t previous_mask_{};
  bool stopping_ = false;  // set under mutex_ before the watcher is woken to end
  std::thread watcher_;
};

}  // namespace hystbench::cli
