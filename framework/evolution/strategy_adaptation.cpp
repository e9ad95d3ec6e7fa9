#include "framework/evolution/strategy_adaptation.hpp"

namespace hystbench {

StrategyAdaptation::StrategyAdaptation(int strategies, int learning_period, double epsilon)
    : learning_period_(learning_period),
      epsilon_(epsilon),
      current_{std::vector<long>(strategies, 0), std::vector<long>(strategies, 0)},
      p_(strategies, 1.0 / strategies) {}

int StrategyAdaptation::draw(Rng& rng) const {
  const double u = rng.uniform();
  double cumulative = 0.0;
  for (std::size_t k = 0; k + 1 < p_.size(); ++k) {
    cumulative += p_[k];
    if (u < cumulative) return static_cast<int>(k);
  }
  // The last strategy also absorbs the rounding of the cumulative sum.
  return static_cast<int>(p_.size()) - 1;
}

void StrategyAdaptation::record(int strategy, bool success) {
  ++(success ? current_.success : current_.failure)[strategy];
}

void StrategyAdaptation::end_generation() {
  window_.push_back(current_);
  for (auto* counts : {&current_.success, &current_.failure}) counts->assign(counts->size(), 0);
  if (static_cast<int>(window_.size()) > learning_period_) window_.pop_front();
  if (static_cast<int>(window_.size()) == learning_period_) update_probabilities();
}

void StrategyAdaptation::update_probabilities() {
  double total = 0.0;
  for (std::size_t k = 0; k < p_.size(); ++k) {
    long ns = 0, nf = 0;
    for (const auto& g : window_) {
      ns += g.success[k];
      nf += g.failure[k];
    }
    const double rate = ns + nf > 0 ? double(ns) / double(ns + nf) : 0.0;
    p_[k] = rate + epsilon_;
    total += p_[k];
  }
  for (double& p : p_) p /= total;
}

}  // namespace hystbench
