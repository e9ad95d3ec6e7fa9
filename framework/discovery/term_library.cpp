#include "framework/discovery/term_library.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "framework/core/text.hpp"

namespace hystbench {
namespace {

std::string superscript(int p) {
  static const std::array<const char*, 10> digits = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  return p == 1 ? "" : std::string(digits[std::size_t(p % 10)]);
}

// What each stage means for a term, indexed by TermStage: its name, the
// signal it is named by, and where its terms enter.
struct StageRow {
  const char* name;
  TermSignal signal;
  Model::Entry entry;
};
constexpr std::array<StageRow, 4> kStages = {{{"input", TermSignal::Input, Model::Entry::Drive},
                                              {"static", TermSignal::Drive, Model::Entry::Dynamics},
                                              {"dynamics", TermSignal::Resonance, Model::Entry::Dynamics},
                                              {"output", TermSignal::Output, Model::Entry::Output}}};

const StageRow& row(TermStage stage) { return kStages[std::size_t(stage)]; }

// Each signal's symbol and block, indexed by TermSignal.
struct SignalRow {
  const char* symbol;
  TermStage stage;
};
constexpr std::array<SignalRow, 6> kSignals = {{{"u", TermStage::Input},
                                                {"v", TermStage::Static},
                                                {"w", TermStage::Static},
                                                {"x", TermStage::Dynamics},
                                                {"y", TermStage::Output},
                                                {"play", TermStage::Static}}};

const SignalRow& row(TermSignal signal) { return kSignals[std::size_t(signal)]; }

// Both parities of |a|^p, odd first; for p = 0 the factor 1.
std::vector<TermFactor> parities(TermSignal signal, bool rate, int p) {
  if (p == 0) return {{signal, rate, 0, false}};
  return {{signal, rate, p, true}, {signal, rate, p, false}};
}

// Every f(a)·g(a') of one signal up to `degree`: by degree, then the power
// of the signal, then parities.
void single_signal_terms(TermSignal signal, TermStage stage, int degree, std::vector<CandidateTerm>& out) {
  for (int d = 1; d <= degree; ++d)
    for (int p = d; p >= 0; --p) {
      for (const TermFactor& f : parities(signal, false, p))
        for (const TermFactor& g : parities(signal, true, d - p)) {
          CandidateTerm t{stage, {}};
          for (const TermFactor& h : {f, g})
            if (h.power > 0) t.factors.push_back(h);
          out.push_back(t);
        }
    }
}

// a·b of two signals of different places (or their rates), both parities of each.
void product_terms(std::vector<CandidateTerm>& out) {
  constexpr std::array<TermSignal, 4> kChain = {TermSignal::Drive, TermSignal::StaticOutput, TermSignal::Resonance,
                                                TermSignal::Output};
  for (std::size_t i = 0; i < kChain.size(); ++i)
    for (std::size_t j = i + 1; j < kChain.size(); ++j)
      for (bool rate_a : {false, true})
        for (bool rate_b : {false, true})
          for (const TermFactor& a : parities(kChain[i], rate_a, 1))
            for (const TermFactor& b : parities(kChain[j], rate_b, 1)) out.push_back({b.stage(), {a, b}});
}

}  // namespace

std::string term_stage_name(TermStage stage) { return row(stage).name; }

double TermFactor::value(double a) const {
  double m = 1.0;
  if (root && power > 0) m = std::sqrt(std::abs(a));
  else
    for (int i = 0; i < power; ++i) m *= std::abs(a);
  if (odd && power > 0) m = a < 0 ? -m : (a > 0 ? m : 0.0);
  return m;
}

std::string TermFactor::symbol() const {
  const std::string prime = rate ? "'" : "";
  if (signal == TermSignal::Play) return "play(v, " + format_number("%g", 100.0 * radius) + " %)" + prime;
  return row(signal).symbol + prime;
}

std::string TermFactor::text() const {
  if (power == 0) return "";
  const std::string a = symbol();
  if (root) return (odd ? "sign(" + a + ")·" : std::string()) + "√|" + a + "|";
  const bool natural = odd == (power % 2 == 1);  // a^p has this parity already
  if (natural) return a + superscript(power);
  if (power % 2 == 1) return "|" + a + "|" + superscript(power);
  return a + superscript(power - 1) + "·|" + a + "|";
}

TermStage TermFactor::stage() const { return row(signal).stage; }

std::string CandidateTerm::text() const {
  std::vector<std::string> parts;
  for (const TermFactor& f : factors)
    if (f.power > 0) parts.push_back(f.text());
  return join(parts, "·");
}

Model::Entry CandidateTerm::entry() const { return row(stage).entry; }

int CandidateTerm::degree() const {
  int d = 0;
  for (const TermFactor& f : factors) d += f.power;
  return d;
}

bool CandidateTerm::has_root() const {
  return std::any_of(factors.begin(), factors.end(), [](const TermFactor& f) { return f.root; });
}

bool CandidateTerm::of_one_signal() const {
  if (factors.empty()) return false;
  const TermSignal a = factors[0].signal;
  const bool own = a == row(stage).signal || (stage == TermStage::Static && a == TermSignal::StaticOutput);
  int signal_factors = 0, rate_factors = 0;
  for (const TermFactor& f : factors) {
    if (f.signal != a) return false;
    ++(f.rate ? rate_factors : signal_factors);
  }
  return own && signal_factors <= 1 && rate_factors <= 1;
}

TermFactor CandidateTerm::own_factor(bool rate) const {
  for (const TermFactor& f : factors)
    if (f.rate == rate) return f;
  return {factors.empty() ? row(stage).signal : factors[0].signal, rate, 0, false};
}

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
  // Input after the other stages: with no effect between the drive and the
  // static block's output but the gain, an input term and the same static
  // term are one column, and the static block is the simpler place to say
  // it enters. The terms beyond one stage's own signal come last, so that
  // a tie goes to the simpler form.
  for (TermStage stage : {TermStage::Static, TermStage::Dynamics, TermStage::Output, TermStage::Input})
    single_signal_terms(row(stage).signal, stage, degree, out);
  single_signal_terms(TermSignal::StaticOutput, TermStage::Static, degree, out);
  for (TermStage stage : {TermStage::Static, TermStage::Dynamics, TermStage::Output, TermStage::Input})
    for (bool odd : {true, false}) out.push_back({stage, {{row(stage).signal, false, 1, odd, 0.0, true}}});
  for (double radius : {0.10, 0.25, 0.50}) out.push_back({TermStage::Static, {{TermSignal::Play, false, 1, true, radius}}});
  if (degree >= 2) product_terms(out);
  return out;
}

Eigen::VectorXd factor_signal(const TermFactor& f, const ModelData& data, const Model::ChainSignals& chain) {
  Eigen::VectorXd a;
  switch (f.signal) {
    case TermSignal::Input: a = data.u; break;
    case TermSignal::Drive: a = chain.v; break;
    case TermSignal::StaticOutput: a = chain.w; break;
    case TermSignal::Resonance: a = chain.resonance; break;
    case TermSignal::Output: a = chain.x; break;
    case TermSignal::Play: {
      // The radius from the estimation samples only, which alone choose the terms.
      a = play_operator(chain.v, f.radius * (chain.v.array().abs() * data.estimation.array()).maxCoeff());
      break;
    }
  }
  return f.rate ? rate_of(a, data.sample_time) : a;
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

Eigen::VectorXd play_operator(const Eigen::VectorXd& a, double r) {
  Eigen::VectorXd p(a.size());
  double state = 0.0;
  for (Eigen::Index k = 0; k < a.size(); ++k) {
    state = std::min(a[k] + r, std::max(a[k] - r, state));
    p[k] = state;
  }
  return p;
}

}  // namespace hystbench
