#pragma once
// The machine and software a comparison ran on, for the report's header.
#include <string>

namespace hystbench::peer {

struct MachineInfo {
  std::string cpu;       // "model name" of /proc/cpuinfo
  unsigned cores = 0;    // hardware threads
  std::string compiler;
  std::string pagmo_version;
  std::string hystbench_commit;  // `git describe` of the checkout it runs in
  std::string date;      // UTC
};

MachineInfo machine_info();
// "1.52 1.61 1.70": the 1, 5 and 15 minute load averages, now.
std::string load_average();

}  // namespace hystbench::peer
