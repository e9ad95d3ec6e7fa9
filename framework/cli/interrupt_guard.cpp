#include "framework/cli/interrupt_guard.hpp"

#include <pthread.h>

#include <cstdio>
#include <cstdlib>

namespace hystbench::cli {

InterruptGuard::InterruptGuard() {
  sigemptyset(&signals_);
  sigaddset(&signals_, SIGINT);
  sigaddset(&signals_, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &signals_, &previous_mask_);
  message_ = [] { return std::string("interrupted before any trial ran; nothing was written"); };
  watcher_ = std::thread([this] { watch(); });
}

InterruptGuard::~InterruptGuard() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  pthread_kill(watcher_.native_handle(), SIGTERM);
  watcher_.join();
  pthread_sigmask(SIG_SETMASK, &previous_mask_, nullptr);
}

void InterruptGuard::set_message(std::function<std::string()> message) {
  std::lock_guard<std::mutex> lock(mutex_);
  message_ = std::move(message);
}

void InterruptGuard::watch() {
  int signal = 0;
  while (sigwait(&signals_, &signal) != 0) {
  }
  std::lock_guard<std::mutex> lock(mutex_);
  if (stopping_) return;
  // Past a progress line, then one message; _Exit: the running trials are
  // abandoned, not waited for, and nothing half-done is flushed.
  const std::string text = "\nhystbench: " + message_() + "\n";
  std::fwrite(text.data(), 1, text.size(), stderr);
  std::fflush(stderr);
  std::_Exit(128 + signal);
}

}  // namespace hystbench::cli
