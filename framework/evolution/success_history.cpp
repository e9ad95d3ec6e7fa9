#include "framework/evolution/success_history.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace hystbench {

void SuccessSet::add(double F, double CR, double f_parent, double f_trial) {
  const double gain = f_parent - f_trial;
  if (!std::isfinite(gain)) return;
  F_.push_back(F);
  CR_.push_back(CR);
  gain_.push_back(gain);
}

double weighted_lehmer_mean(const std::vector<double>& values, const std::vector<double>& weights) {
  if (values.empty() || values.size() != weights.size())
    throw std::logic_error("weighted_lehmer_mean: values and weights must match and be non-empty");
  // Gains of diverging candidates can be finite yet near DBL_MAX: their sum
  // overflows, and every weight would become 0 (the mean 0/0). Scaling by
  // the largest gain first keeps the same weights.
  double scale = 1.0;
  double total = std::accumulate(weights.begin(), weights.end(), 0.0);
  if (!std::isfinite(total)) {
    scale = *std::max_element(weights.begin(), weights.end());
    total = 0.0;
    for (double w : weights) total += w / scale;
  }
  double squares = 0.0, plain = 0.0;
  for (std::size_t m = 0; m < values.size(); ++m) {
    const double w = weights[m] / scale / total;
    squares += w * values[m] * values[m];
    plain += w * values[m];
  }
  return squares / plain;
}

SuccessHistory::SuccessHistory(int size, double f_init, double cr_init, MemoryUpdate rule)
    : mu_f_(size, f_init), mu_cr_(size, cr_init), rule_(rule) {
  if (size < 1) throw std::logic_error("SuccessHistory: at least one memory slot");
}

void SuccessHistory::update(const SuccessSet& s) {
  if (s.empty()) return;
  const double f_mean = weighted_lehmer_mean(s.F(), s.gain());
  // All successful CR being 0 makes the Lehmer mean 0/0: that is the
  // signal to switch the slot to TERMINAL.
  const bool all_cr_zero = *std::max_element(s.CR().begin(), s.CR().end()) == 0.0;
  const double cr_mean = all_cr_zero ? kTerminal : weighted_lehmer_mean(s.CR(), s.gain());
  double& f = mu_f_[position_];
  double& cr = mu_cr_[position_];
  if (rule_ == MemoryUpdate::Replace) {
    f = f_mean;
    cr = is_terminal(cr) ? kTerminal : cr_mean;
  } else {
    f = (f_mean + f) / 2;
    cr = (cr_mean + cr) / 2;
  }
  position_ = (position_ + 1) % size();
}

double draw_cr(double mu_cr, Rng& rng) {
  if (SuccessHistory::is_terminal(mu_cr)) return 0.0;
  return std::clamp(rng.normal(mu_cr, 0.1), 0.0, 1.0);
}

double draw_f(double mu_f, Rng& rng) {
  double F = 0.0;
  do {
    F = rng.cauchy(mu_f, 0.1);
  } while (F <= 0.0);
  return std::min(F, 1.0);
}

}  // namespace hystbench
