#pragma once
// Success-based strategy probabilities of SaDE (A. K. Qin, V. L. Huang,
// P. N. Suganthan, IEEE TEVC 13(2):398-417, 2009) as
// docs/algorithms.md#strategy-selection states them: per strategy k,
// successes ns_k and failures nf_k of the last LP generations give
// S_k = sum ns_k / (sum ns_k + sum nf_k) + eps and
// p_k = S_k / sum_m S_m; p_k = 1/K until LP generations have been recorded.
// A strategy not tried in the window counts as success rate 0 (S_k = eps)
// rather than 0/0.
#include <deque>
#include <vector>

#include "framework/core/rng.hpp"

namespace hystbench {

class StrategyAdaptation {
 public:
  StrategyAdaptation(int strategies, int learning_period, double epsilon = 0.01);

  const std::vector<double>& probabilities() const { return p_; }
  // Roulette wheel over probabilities(): one U(0,1) draw.
  int draw(Rng& rng) const;
  // Outcome of one trial built with `strategy` in the current generation;
  // success means strictly better than its target.
  void record(int strategy, bool success);
  // Closes the generation: its counts enter the window, the oldest leave it,
  // and the probabilities are recomputed once the window is full.
  void end_generation();

 private:
  struct Counts {
    std::vector<long> success, failure;
  };
  void update_probabilities();

  int learning_period_;
  double epsilon_;
  std::deque<Counts> window_;
  Counts current_;
  std::vector<double> p_;
};

}  // namespace hystbench
