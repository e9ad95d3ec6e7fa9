#pragma once
// The candidate terms of a proposal (docs/discovery.md#proposing-a-missing-term):
// powers and products of one signal of the fitted chain and of its rate,
// each entering the chain where that signal lives:
//
//   stage      built from                              added to
//   input      u, the measured input                   the drive v, before the gain
//   static     v, the drive                            the dynamics' input w
//   dynamics   x, the first dynamics effect's output   the dynamics' input w (a force
//              (the resonance, msd in the seed chain)  that depends on the state)
//   output     y, the dynamics' output                 the output
//
// A term is f(a)·g(a') with a the stage's signal, a' = (a[k] − a[k−1])/Ts its
// rate (0 at the first sample), and each factor |a|ᵖ or
// |a|ᵖ·sign(a): both parities of every power, so that a·|a| (an odd
// square) and |a|³ (an even cube) are candidates beside a² and a³. Every
// term up to a total degree (default 3) at every stage.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "framework/model/model.hpp"

namespace hystbench {

// The order indexes the stage table of term_library.cpp.
enum class TermStage { Input, Static, Dynamics, Output };

// "input", "static", "dynamics", "output".
std::string term_stage_name(TermStage stage);

// |a|^power · sign(a) when odd, |a|^power when not; 1 for power 0.
struct TermFactor {
  int power = 0;
  bool odd = false;

  double value(double a) const;
  // "v", "|v|", "v²", "v·|v|", "|v|³", ... for the symbol a ("" for power 0).
  std::string text(const std::string& a) const;
};

struct CandidateTerm {
  TermStage stage = TermStage::Static;
  TermFactor signal, rate;

  // The stage's signal: "u", "v", "x" or "y".
  std::string symbol() const;
  // "v·|v'|", "x³", ...
  std::string text() const;
  Model::Entry entry() const;
  // The term at one sample from the stage's signal and its rate.
  double value(double a, double a_rate) const { return signal.value(a) * rate.value(a_rate); }
};

// Every term of total degree 1..degree at every stage, in a fixed order
// (stage: static, dynamics, output, input; then degree, then the power of
// the signal, then parities).
std::vector<CandidateTerm> term_library(int degree);

// Where a term enters: "drive v", "dynamics input w" or "output".
std::string entry_name(Model::Entry entry);

// The signal terms of `stage` are built from, on every sample of one
// simulation (normalised units): u from the data, the rest from the chain.
const Eigen::VectorXd& stage_signal(TermStage stage, const ModelData& data, const Model::ChainSignals& chain);

// (a[k] − a[k−1]) / Ts, and 0 at k = 0 (no rate before the record).
Eigen::VectorXd rate_of(const Eigen::VectorXd& a, double sample_time);

}  // namespace hystbench
