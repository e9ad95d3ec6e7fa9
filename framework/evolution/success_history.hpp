#pragma once
// Success-history adaptation of F and CR, the SHADE family's parameter
// control (docs/algorithms.md#success-history): H memory slots of (mu_F, mu_CR), each
// generation's successful values folded into one slot by a weighted Lehmer
// mean, slots overwritten in turn.
#include <vector>

#include "framework/core/rng.hpp"

namespace hystbench {

// The F, CR and fitness gain of the strict improvements of one generation.
class SuccessSet {
 public:
  // Records a success. A pair with an infinite (or NaN) gain carries no
  // usable weight and is left out (docs/algorithms.md#infinite-fitness).
  void add(double F, double CR, double f_parent, double f_trial);
  bool empty() const { return F_.empty(); }
  const std::vector<double>& F() const { return F_; }
  const std::vector<double>& CR() const { return CR_; }
  const std::vector<double>& gain() const { return gain_; }

 private:
  std::vector<double> F_, CR_, gain_;
};

// sum(w v^2) / sum(w v) with w_m = weights_m / sum(weights). Requires equal,
// non-zero lengths and sum(w v) > 0.
double weighted_lehmer_mean(const std::vector<double>& values, const std::vector<double>& weights);

enum class MemoryUpdate {
  // L-SHADE paper: the slot takes the new means; CR's TERMINAL is sticky.
  Replace,
  // jSO reference code: the slot becomes (new mean + old value) / 2, with
  // TERMINAL (-1) averaged like a number.
  AverageWithOld,
};

class SuccessHistory {
 public:
  // mu_CR value meaning "CR = 0 from now on" (the paper's bottom symbol).
  static constexpr double kTerminal = -1.0;
  // Any negative mu_CR is terminal: jSO's averaging can produce values in (-1, 0).
  static bool is_terminal(double mu_cr) { return mu_cr < 0.0; }

  SuccessHistory(int size, double f_init, double cr_init, MemoryUpdate rule);

  int size() const { return static_cast<int>(mu_f_.size()); }
  double mu_f(int slot) const { return mu_f_[slot]; }
  double mu_cr(int slot) const { return mu_cr_[slot]; }
  int position() const { return position_; }  // next slot to be written

  // Folds one generation's successes into the current slot and moves to the
  // next; an empty set changes nothing (the index does not advance).
  void update(const SuccessSet& successes);

 private:
  std::vector<double> mu_f_, mu_cr_;
  MemoryUpdate rule_;
  int position_ = 0;
};

// CR_i = 0 for a terminal mu_CR, else clip(N(mu_CR, 0.1), 0, 1).
double draw_cr(double mu_cr, Rng& rng);
// F_i = Cauchy(mu_F, 0.1), redrawn while <= 0, capped at 1.
double draw_f(double mu_f, Rng& rng);

}  // namespace hystbench
