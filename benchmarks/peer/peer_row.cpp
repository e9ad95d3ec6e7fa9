#include "benchmarks/peer/peer_row.hpp"

#include <algorithm>

namespace hystbench::peer {
namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t h = v.size() / 2;
  return v.size() % 2 == 1 ? v[h] : 0.5 * (v[h - 1] + v[h]);
}

}  // namespace

PeerRow summarise(PeerRow row, const std::vector<PeerTrial>& trials, double noise_floor) {
  std::vector<double> best;
  double evaluations = 0.0;
  double wall = 0.0;
  for (const PeerTrial& t : trials) {
    best.push_back(t.best / noise_floor);
    evaluations += double(t.evaluations);
    wall += t.wall_seconds;
  }
  row.trials = static_cast<long>(trials.size());
  row.evaluations = evaluations / double(trials.size());
  row.wall_seconds = wall;
  row.evaluations_per_second = evaluations / wall;
  row.median_over_floor = median(best);
  row.best_over_floor = *std::min_element(best.begin(), best.end());
  return row;
}

}  // namespace hystbench::peer
