// Second vibration mode in parallel with the chain's dynamics (dynamics stage).
//
//   m = H2·w,   H2(s) = 1 / (κ²s² + 2ζκs + 1),   κ = 1 / (2π·10^log10_f)
//   signal[k] = (1 − g)·signal[k] + g·m[k]
//
// w is the stage input (the signal entering the dynamics stage); signal is
// the output of the dynamics effects listed before this one (usually msd,
// the first mode). The two modes share the static compliance: g (parameter
// `participation`) is the second mode's share of it, so the static gain stays
// the model's gain and g cannot be traded against it; above both resonances
// the response rolls off as a modal sum does. For a cantilever the second
// mode sits near 6.3 times the first.
// H2 is discretised bilinearly from rest, like msd. The frequency is a
// log10 parameter because the mode may sit anywhere from a few Hz to well
// above the first mode; at the neutral value g = 0 the frequency and damping
// do not matter and the output is exactly unchanged. ζ ≤ 0 makes apply false.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "framework/model/kernel_effect.hpp"
#include "framework/model/spectrum.hpp"
#include "problems/hammerstein/effects/biquad.hpp"

namespace hystbench {
namespace {

// Share of the input power that makes the main excitation band, and the
// fewest residual bins above it worth a median.
constexpr double kMainBandShare = 0.95;
constexpr std::size_t kFewestBins = 8;

// Index of the first spectrum bin above the band holding kMainBandShare of the power.
std::size_t main_band_end(const Spectrum& s) {
  double total = 0, cumulative = 0;
  for (double p : s.power) total += p;
  std::size_t end = 0;
  while (end < s.power.size() && cumulative < kMainBandShare * total) cumulative += s.power[end++];
  return end;
}

// Signature statistic: the largest bin of the residual's Welch spectrum above
// the main excitation band, over the median bin there, and its frequency. A
// second mode the model lacks is a lightly damped resonance: it leaves a
// narrow peak in the residual spectrum where the input crosses it (a sweep, a
// harmonic), high above the level of the rest. The main band, below which 95 %
// of the input power lies, is left out: there every error of the main
// response shows. A white residual gives a flat spectrum, a ratio of about 1
// to 2 (the χ² spread of the averaged bins). (Welch 1967; Meirovitch,
// Fundamentals of Vibrations, 2001, modal superposition.)
SignatureValue residual_spectral_peak(const ResidualView& r) {
  const Spectrum input = welch_spectrum(r.u, r.sample_time);
  const Spectrum residual = welch_spectrum(r.e, r.sample_time);
  const std::size_t begin = main_band_end(input);
  if (begin == 0 || begin + kFewestBins > residual.power.size()) return {};
  std::vector<double> above(residual.power.begin() + long(begin), residual.power.end());
  const auto highest_bin = std::max_element(above.begin(), above.end());
  const std::size_t peak = std::size_t(highest_bin - above.begin());
  const double highest = above[peak];
  std::nth_element(above.begin(), above.begin() + long(above.size() / 2), above.end());
  const double median = above[above.size() / 2];
  if (!(median > 0)) return {};
  return {highest / median,
          {{"frequency", residual.frequency[begin + peak]},
           {"band", input.frequency[begin - 1]}}};
}

class SecondMode : public KernelEffect<SecondMode, 4, EffectDrive::StageInput> {
 public:
  static EffectInfo info() {
    EffectInfo i;
    i.name = "second_mode";
    i.summary =
        "second vibration mode: a parallel unit-gain resonance taking a share g of the static "
        "compliance";
    i.citation =
        "Meirovitch, Fundamentals of Vibrations, 2001 (modal superposition; cantilever "
        "ω₂/ω₁ ≈ 6.27); docs/discovery.md";
    i.stage = EffectStage::Dynamics;
    i.params = {
        {"participation", -1.0, 1.0, 0.0, 0, 0, "",
         "g: share of the static gain carried by the second mode"},
        {"log10_f", 0.0, 4.5, 2.5, 0, 0, "log10(Hz)", "log10 of the second natural frequency"},
        {"zeta", 0.005, 1.0, 0.05, 0, 0, "", "damping ratio of the second mode"},
    };
    i.signature =
        "the residual spectrum has a narrow peak at a second frequency and the error bursts when "
        "a sweep crosses it";
    i.statistic = {"residual spectrum peak / median above the band", residual_spectral_peak,
                   "the residual spectrum has a narrow peak at {frequency} Hz, {value} times its "
                   "median level above the main excitation band (which ends near {band} Hz)"};
    return i;
  }

  // c = (g, b, a1, a2): the participation g and H2(z) = b·(1, 2, 1) / (1, a1, a2).
  static EffectSetup setup(std::span<const double> p, double Ts, std::array<double, 4>& c) {
    const double g = p[0], log10_f = p[1], zeta = p[2];
    if (!std::isfinite(g) || !std::isfinite(log10_f) || !std::isfinite(zeta)) return EffectSetup::Invalid;
    if (g == 0.0) return EffectSetup::PassThrough;
    if (!(zeta > 0.0) || !(Ts > 0.0) || !std::isfinite(Ts)) return EffectSetup::Invalid;
    // k = 2κ/Ts; H2(z) = (1, 2, 1) / (k² + q + 1, 2 − 2k², k² − q + 1), q = 2ζk.
    const double omega = 2.0 * std::numbers::pi * std::pow(10.0, log10_f);
    const auto [k2, q, a0] = tustin_resonance(2.0 / (omega * Ts), zeta);
    c = {g, 1.0 / a0, (2.0 - 2.0 * k2) / a0, (k2 - q + 1.0) / a0};
    if (!std::isfinite(c[2]) || !std::isfinite(c[3]) || !(c[1] > 0.0)) return EffectSetup::Invalid;
    return EffectSetup::Run;
  }

  // H2 at rest: w[k<0] = m[k<0] = 0.
  template <class V>
  struct State {
    V w1{}, w2{}, m1{}, m2{};
  };

  // One sample: the second mode's response m to the stage input w, mixed in
  // with share g.
  template <class V>
  static V sample(const std::array<V, 4>& c, NoAux, State<V>& state, V signal, V w) {
    const V m = (c[1] * ((w + 2.0 * state.w1) + state.w2) - c[3] * state.m2) - c[2] * state.m1;
    state.w2 = state.w1;
    state.w1 = w;
    state.m2 = state.m1;
    state.m1 = m;
    return signal + c[0] * (m - signal);
  }

  template <class V>
  static V health(const std::array<V, 4>&, const State<V>& state) {
    return state.m1;
  }
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_EFFECT(hystbench::SecondMode)
