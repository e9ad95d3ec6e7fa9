#include "framework/harness/status_line.hpp"

#include <unistd.h>

#include <atomic>
#include <ctime>

#include "framework/core/text.hpp"

namespace hystbench {
namespace {

std::atomic<bool> quiet{false};

}  // namespace

bool stderr_is_terminal() { return isatty(fileno(stderr)) != 0; }

void set_quiet(bool q) { quiet = q; }

ProgressMode progress_mode() {
  if (quiet) return ProgressMode::Quiet;
  return stderr_is_terminal() ? ProgressMode::Terminal : ProgressMode::Log;
}

StatusLine::StatusLine(ProgressMode mode, std::FILE* out, StatusTiming timing)
    : mode_(mode), out_(out), timing_(timing) {
  if (mode_ == ProgressMode::Log) heartbeat_ = std::thread([this] { heartbeat_loop(); });
}

StatusLine::~StatusLine() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  if (heartbeat_.joinable()) heartbeat_.join();
}

double StatusLine::elapsed() const {
  return std::chrono::duration<double>(Clock::now() - start_).count();
}

void StatusLine::write_log_line(const std::string& text, const char* note) {
  std::fprintf(out_, "[%s] %s   elapsed %.0f s%s\n", time_now("%Y-%m-%d %H:%M:%S", false).c_str(), text.c_str(), elapsed(),
               note);
  std::fflush(out_);
  last_line_ = Clock::now();
  pending_ = false;
  written_ = true;
}

void StatusLine::show(const std::string& text) {
  if (mode_ == ProgressMode::Quiet) return;
  std::lock_guard<std::mutex> lock(mutex_);
  if (mode_ == ProgressMode::Terminal) {
    std::fprintf(out_, "\r  %s   elapsed %.0f s\033[K", text.c_str(), elapsed());
    std::fflush(out_);
    shown_ = true;
    return;
  }
  if (text == latest_) return;
  latest_ = text;
  pending_ = true;
  if (!written_ || Clock::now() - last_line_ >= timing_.log_gap)
    write_log_line(latest_, "");
}

void StatusLine::finish() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (mode_ == ProgressMode::Terminal && shown_) std::fprintf(out_, "\n");
  if (mode_ == ProgressMode::Log && pending_) write_log_line(latest_, "");
  shown_ = false;
}

// A log line at least every `heartbeat`, while the job runs.
void StatusLine::heartbeat_loop() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!stop_) {
    wake_.wait_for(lock, timing_.heartbeat / 4);
    if (stop_) break;
    if (!latest_.empty() && Clock::now() - last_line_ >= timing_.heartbeat)
      write_log_line(latest_, pending_ ? "" : " (still running)");
  }
}

}  // namespace hystbench
