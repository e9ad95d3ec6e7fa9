#pragma once
// Runs the built `hystbench` program as a user would and captures what it
// printed and how it exited.
#include <sys/wait.h>

#include <cstdio>
#include <string>

namespace hystbench::test_support {

struct Outcome {
  int code;
  std::string output;  // stdout and stderr
};

// `in_dir`: the folder to run it in, as a user working there would (default:
// the test's own).
inline Outcome hystbench(const std::string& args, const std::string& in_dir = "") {
  const std::string command =
      (in_dir.empty() ? "" : "cd '" + in_dir + "' && ") + std::string(HYSTBENCH_EXE) + " " + args + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  std::string out;
  char buf[4096];
  while (std::size_t n = fread(buf, 1, sizeof buf, pipe)) out.append(buf, n);
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

}  // namespace hystbench::test_support
