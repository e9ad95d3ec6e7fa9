#include "framework/discovery/term_library.hpp"

#include <array>
#include <cmath>

namespace hystbench {
namespace {

std::string superscript(int p) {
  static const std::array<const char*, 10> digits = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  return p == 1 ? "" : std::string(digits[std::size_t(p % 10)]);
}

// Both parities of |a|^p, odd first.
std::vector<TermFactor> factors(int p) {
  if (p == 0) return {TermFactor{}};
  return {{p, true}, {p, false}};
}

// What each stage means for a term, indexed by TermStage: its name, the
// symbol of the signal terms are built from, and where they enter.
struct StageRow {
  const char* name;
  const char* symbol;
  Model::Entry entry;
};
constexpr std::array<StageRow, 4> kStages = {{{"input", "u", Model::Entry::Drive},
                                              {"static", "v", Model::Entry::Dynamics},
                                              {"dynamics", "x", Model::Entry::Dynamics},
                                              {"output", "y", Model::Entry::Output}}};

const StageRow& row(TermStage stage) { return kStages[std::size_t(stage)]; }

}  // namespace

std::string term_stage_name(TermStage stage) { return row(stage).name; }

double TermFactor::value(double a) const {
  double m = 1.0;
  for (int i = 0; i < power; ++i) m *= std::abs(a);
  if (odd && power > 0) m = a < 0 ? -m : (a > 0 ? m : 0.0);
  return m;
}

std::string TermFactor::text(const std::string& a) const {
  if (power == 0) return "";
  const bool natural = odd == (power % 2 == 1);  // a^p has this parity already
  if (natural) return a + superscript(power);
  if (power % 2 == 1) return "|" + a + "|" + superscript(power);
  return a + superscript(power - 1) + "·|" + a + "|";
}

std::string CandidateTerm::symbol() const { return row(stage).symbol; }

std::string CandidateTerm::text() const {
  const std::string a = signal.text(symbol()), b = rate.text(symbol() + "'");
  if (a.empty()) return b;
  if (b.empty()) return a;
  return a + "·" + b;
}

Model::Entry CandidateTerm::entry() const { return row(stage).entry; }

std::string entry_name(Model::Entry entry) {
  switch (entry) {
    case Model::Entry::Drive: return "drive v";
    case Model::Entry::Dynamics: return "dynamics input w";
    case Model::Entry::Output: return "output";
  }
  return "?";
}

std::vector<CandidateTerm> term_library(int degree) {
  std::vector<CandidateTerm> out;
  // Input last: with no effect between the drive and the static block's
  // output but the gain, an input term and the same static term are one
  // column, and the static block is the simpler place to say it enters.
  for (TermStage stage : {TermStage::Static, TermStage::Dynamics, TermStage::Output, TermStage::Input})
    for (int d = 1; d <= degree; ++d)
      for (int p = d; p >= 0; --p)
        for (const TermFactor& f : factors(p))
          for (const TermFactor& g : factors(d - p)) out.push_back({stage, f, g});
  return out;
}

const Eigen::VectorXd& stage_signal(TermStage stage, const ModelData& data, const Model::ChainSignals& chain) {
  switch (stage) {
    case TermStage::Input: return data.u;
    case TermStage::Static: return chain.v;
    case TermStage::Dynamics: return chain.resonance;
    case TermStage::Output: return chain.x;
  }
  return chain.x;
}

Eigen::VectorXd rate_of(const Eigen::VectorXd& a, double sample_time) {
  Eigen::VectorXd r(a.size());
  double previous = a.size() ? a[0] : 0.0;
  for (Eigen::Index k = 0; k < a.size(); ++k) {
    r[k] = (a[k] - previous) / sample_time;
    previous = a[k];
  }
  return r;
}

}  // namespace hystbench
