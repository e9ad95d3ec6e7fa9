#include "benchmarks/peer/machine_info.hpp"

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

}  // namespace

MachineInfo machine_info() {
  const auto p = provenance(1, 0);
  return {cpu_model(),
          std::thread::hardware_concurrency(),
          p.value("compiler", ""),
          pagmo_version(),
          p.value("git_commit", ""),
          p.value("date", "")};
}

std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string one, five, fifteen;
  if (!(in >> one >> five >> fifteen)) return "unknown";
  return one + " " + five + " " + fifteen;
}

}  // namespace hystbench::peer
