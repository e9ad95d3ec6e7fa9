#pragma once
// The progress display of every long command (fit, diagnose, discover, svr,
// track, control, run): what is being done and the elapsed time.
//
// On a terminal it is one self-rewriting line. In a log (stderr redirected)
// it is timestamped lines: a new status once at least `log_gap` has passed
// since the last line, and a heartbeat repeating the latest status whenever
// `heartbeat` passes without a line, so that a log shows the job is alive at
// least once a minute. --quiet silences it. Safe to call from several
// threads.
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <string>
#include <thread>

namespace hystbench {

enum class ProgressMode { Terminal, Log, Quiet };

// True when stderr is an interactive terminal.
bool stderr_is_terminal();

// Quiet after set_quiet(true) (--quiet); else Terminal when stderr is a
// terminal, Log otherwise.
ProgressMode progress_mode();
void set_quiet(bool quiet);

struct StatusTiming {
  std::chrono::milliseconds log_gap{10'000};
  std::chrono::milliseconds heartbeat{60'000};
};

class StatusLine {
 public:
  explicit StatusLine(ProgressMode mode = progress_mode(), std::FILE* out = stderr,
                      StatusTiming timing = {});
  ~StatusLine();
  StatusLine(const StatusLine&) = delete;
  StatusLine& operator=(const StatusLine&) = delete;

  void show(const std::string& text);
  // Ends the terminal line (if anything was shown); in a log, writes the
  // latest status if it was held back.
  void finish();

 private:
  using Clock = std::chrono::steady_clock;
  void write_log_line(const std::string& text, const char* note);  // mutex held
  void heartbeat_loop();
  double elapsed() const;

  ProgressMode mode_;
  std::FILE* out_;
  StatusTiming timing_;
  Clock::time_point start_ = Clock::now();
  Clock::time_point last_line_ = Clock::now();
  std::string latest_;
  bool shown_ = false;    // terminal: a line is open
  bool written_ = false;  // log: a line was written
  bool pending_ = false;  // log: `latest_` was not written yet
  bool stop_ = false;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::thread heartbeat_;
};

}  // namespace hystbench
