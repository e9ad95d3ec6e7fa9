#pragma once
// One line of the side-by-side table: a framework's algorithm summarised
// over its seeded trials.
#include <string>
#include <vector>

#include "benchmarks/peer/peer_trial.hpp"

namespace hystbench::peer {

struct PeerRow {
  std::string section;    // "equal budget", "MEDE Table 1 protocol", "overhead", "ga replacement"
  std::string framework;  // "hystbench" or "pagmo"
  std::string algorithm;
  std::string settings;   // population and anything not at its default
  std::string budget;     // e.g. "20000 evaluations", "100 generations"
  int threads = 1;
  long trials = 0;
  double evaluations = 0.0;     // mean per trial
  double wall_seconds = 0.0;    // summed over trials
  double evaluations_per_second = 0.0;
  double median_over_floor = 0.0;  // final fitness / noise-floor SSE
  double best_over_floor = 0.0;
};

// Fills trials, evaluations, wall time, throughput and the fitness ratios of
// `row` from `trials`.
PeerRow summarise(PeerRow row, const std::vector<PeerTrial>& trials, double noise_floor);

}  // namespace hystbench::peer
