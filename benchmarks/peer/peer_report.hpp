#pragma once
// The comparison's outputs: peer.md (tables beside the machine they ran on)
// and peer.csv (one line per row, every section).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "benchmarks/peer/machine_info.hpp"
#include "benchmarks/peer/peer_row.hpp"
#include "benchmarks/peer/table1_protocol.hpp"

namespace hystbench::peer {

struct PeerReport {
  MachineInfo machine;
  std::string command;      // how the numbers were made
  std::string load_before;  // load averages when the run started and ended
  std::string load_after;
  double noise_floor = 0.0;
  std::vector<PeerRow> rows;
  std::optional<ProtocolTimes> protocol;
};

void write_markdown(const std::filesystem::path& file, const PeerReport& report);
void write_csv(const std::filesystem::path& file, const std::vector<PeerRow>& rows);

}  // namespace hystbench::peer
