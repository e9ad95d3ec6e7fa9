#include "benchmarks/peer/machine_info.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <thread>

#include "benchmarks/peer/pagmo_peer.hpp"
#include "framework/report/provenance.hpp"

namespace hystbench::peer {
namespace {

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("model name", 0) != 0) continue;
    const auto colon = line.find(':');
    if (colon != std::string::npos) return line.substr(line.find_first_not_of(' ', colon + 1));
  }
  return "unknown";
}

// The checkout the program runs in, when it is a git work tree: the commit
// baked in at configure time goes stale as soon as anything is committed.
std::string working_tree_revision(const std::string& fallback) {
  FILE* pipe = popen("git describe --always --dirty --abbrev=12 2>/dev/null", "r");
  if (!pipe) return fallback;
  char buf[128] = {};
  const bool got = std::fgets(buf, sizeof buf, pipe) != nullptr;
  const bool ok = pclose(pipe) == 0 && got;
  std::string s = buf;
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r')) s.pop_back();
  return ok && !s.empty() ? s : fallback;
}

}  // namespace

MachineInfo machine_info() {
  const auto p = provenance(1, 0);
  return {cpu_model(),
          std::thread::hardware_concurrency(),
          p.value("compiler", ""),
          pagmo_version(),
          working_tree_revision(p.value("git_commit", "")),
          p.value("date", "")};
}

std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string one, five, fifteen;
  if (!(in >> one >> five >> fifteen)) return "unknown";
  return one + " " + five + " " + fifteen;
}

}  // namespace hystbench::peer
