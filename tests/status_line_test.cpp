#include "framework/harness/status_line.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <thread>

namespace hystbench {
namespace {

// Everything written to `f` so far.
std::string contents(std::FILE* f) {
  std::fflush(f);
  std::rewind(f);
  std::string out;
  for (int c = std::fgetc(f); c != EOF; c = std::fgetc(f)) out += char(c);
  return out;
}

long lines(const std::string& s) { return long(std::count(s.begin(), s.end(), '\n')); }

TEST(StatusLine, InALogStatusesAreTimestampedLinesAndTheLastIsNeverLost) {
  std::FILE* f = std::tmpfile();
  {
    StatusLine status(ProgressMode::Log, f);
    status.show("discover step 0: restart 1 of 3");
    status.show("discover step 0: restart 2 of 3");  // within the 10 s gap: held back
    EXPECT_EQ(lines(contents(f)), 1);
    status.finish();
  }
  const std::string text = contents(f);
  EXPECT_EQ(lines(text), 2) << text;
  EXPECT_EQ(text.rfind("[20", 0), 0u) << text;
  EXPECT_NE(text.find("] discover step 0: restart 1 of 3   elapsed 0 s\n"), std::string::npos) << text;
  EXPECT_NE(text.find("restart 2 of 3"), std::string::npos) << text;
  std::fclose(f);
}

TEST(StatusLine, InALogAHeartbeatSaysTheJobIsStillRunning) {
  std::FILE* f = std::tmpfile();
  {
    StatusLine status(ProgressMode::Log, f, {std::chrono::milliseconds(10'000), std::chrono::milliseconds(20)});
    status.show("fit msd: restart 1 of 3");
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  const std::string text = contents(f);
  EXPECT_GE(lines(text), 2) << text;
  EXPECT_NE(text.find("fit msd: restart 1 of 3   elapsed 0 s (still running)\n"), std::string::npos) << text;
  std::fclose(f);
}

TEST(StatusLine, OnATerminalItRewritesOneLineAndQuietWritesNothing) {
  std::FILE* f = std::tmpfile();
  {
    StatusLine status(ProgressMode::Terminal, f);
    status.show("a");
    status.show("b");
    status.finish();
  }
  EXPECT_EQ(contents(f), "\r  a   elapsed 0 s\033[K\r  b   elapsed 0 s\033[K\n");
  std::FILE* g = std::tmpfile();
  {
    StatusLine status(ProgressMode::Quiet, g);
    status.show("a");
    status.finish();
  }
  EXPECT_EQ(contents(g), "");
  std::fclose(f);
  std::fclose(g);
}

}  // namespace
}  // namespace hystbench
