#pragma once
// The candidate terms of a proposal (docs/discovery.md#proposing-a-missing-term):
// powers and products of the fitted chain's own signals, each term entering
// the chain in the block where its latest signal lives:
//
//   signal                                         block     a term enters at
//   u, the measured input                          input     the drive v, before the gain
//   v, the drive                                   static    the dynamics' input w
//   w, the static block's output (dynamics input)  static    w
//   play(v, r), a play operator on v               static    w
//   x, the first dynamics effect's output          dynamics  w (a force that depends
//      (the resonance, msd in the seed chain)                on the state)
//   y, the dynamics' output                        output    the output
//
// Each factor is |a|ᵖ or |a|ᵖ·sign(a) of a signal a or of its rate
// a' = (a[k] − a[k−1])/Ts (0 at the first sample): both parities of every
// power, so that a·|a| (an odd square) and |a|³ (an even cube) are
// candidates beside a² and a³. The library holds
//   - every f(a)·g(a') of one signal and its rate, up to a total degree
//     (default 3), for u, v, x, y and w;
//   - the play operator on v at radii of 10, 25 and 50 % of max |v| on the
//     estimation samples (the state of a backlash-like hysteresis the chain
//     lacks);
//   - products of two signals of different places (v, w, x, y, or their
//     rates), each to the first power, both parities: degree 2;
//   - the square root √|a| of each block's own signal, both parities
//     (sign(a)·√|a| and √|a|): the outflow of a tank through an orifice
//     (Torricelli), and any law that grows slower than linear. Degree 1.
#include "framework/core/eigen.hpp"
#include <string>
#include <vector>

#include "framework/model/model.hpp"

namespace hystbench {

// The block a term enters; the order indexes the stage table of term_library.cpp.
enum class TermStage { Input, Static, Dynamics, Output };

// "input", "static", "dynamics", "output".
std::string term_stage_name(TermStage stage);

// The signals of the fitted chain a factor can be built from.
enum class TermSignal { Input, Drive, StaticOutput, Resonance, Output, Play };

// One factor: |a|^power · sign(a) when odd, |a|^power when not, with a the
// signal (or its rate); √|a| in place of |a|^power when `root`.
struct TermFactor {
  TermSignal signal = TermSignal::Drive;
  bool rate = false;
  int power = 0;  // 0: the factor is 1; 1 for a root
  bool odd = false;
  double radius = 0.0;  // play operators: the radius as a share of max |v|
  bool root = false;    // |a|^(1/2); its power is 1

  // The exponent of |a|: power, or 0.5 for a root.
  double exponent() const { return root ? 0.5 : double(power); }

  double value(double a) const;
  // "v", "|v|", "v²", "v·|v|", "|v'|³", "play(v, 25 %)", "√|y|", "sign(y)·√|y|", ...
  std::string text() const;
  // "u", "v", "w", "x", "y" or "play(v, 25 %)"; with "'" for a rate.
  std::string symbol() const;
  // The block the signal belongs to.
  TermStage stage() const;
};

struct CandidateTerm {
  TermStage stage = TermStage::Static;
  std::vector<TermFactor> factors;  // their product; at least one

  // "v·|v'|", "x³", "v·x'", ...
  std::string text() const;
  Model::Entry entry() const;
  // The sum of the factors' powers; a root counts 1.
  int degree() const;
  // True when a factor is a root: the term's coefficient has a fractional
  // unit, so it is reported in normalised units.
  bool has_root() const;
  // True when the term is f(a)·g(a') of one signal of its own block and
  // that signal's rate (u; v or w; x; y): the form a generated effect
  // (effect_source.hpp) has.
  bool of_one_signal() const;
  // For such a term, the factor of the signal (rate false) or of its rate;
  // power 0 when the term has none.
  TermFactor own_factor(bool rate) const;
};

// Every term of the library, in a fixed order: first f(a)·g(a') of the
// stages' own signals (static v, dynamics x, output y, input u; each by
// degree, the power of the signal, parities), then w, the square roots of
// the blocks' own signals, the play operators and the products of two
// signals. `degree` (1 to 6) bounds f·g; the
// products need degree ≥ 2.
std::vector<CandidateTerm> term_library(int degree);

// Where a term enters: "drive v", "dynamics input w" or "output".
std::string entry_name(Model::Entry entry);

// The signal a factor is built from, on every sample of one simulation
// (normalised units), or its rate: u from the data, the rest from the
// chain; the play operator's radius is a share of max |v| over the
// estimation samples.
Eigen::VectorXd factor_signal(const TermFactor& f, const ModelData& data, const Model::ChainSignals& chain);

// (a[k] − a[k−1]) / Ts, and 0 at k = 0 (no rate before the record).
Eigen::VectorXd rate_of(const Eigen::VectorXd& a, double sample_time);

// The play (backlash) operator of radius r from p = 0 (clamped into
// [a[0] − r, a[0] + r] at the first sample): p[k] = min(a[k] + r, max(a[k] − r, p[k−1])).
Eigen::VectorXd play_operator(const Eigen::VectorXd& a, double r);

}  // namespace hystbench
