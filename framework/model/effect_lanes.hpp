#pragma once
// Blocks of candidates for the discovery models: kEffectLanes candidates
// advance through the effect chain together, candidate l in vector lane l.
// The recurrences of the effects are latency-bound one candidate at a time;
// a lane vector carries kEffectLanes of them for the price of one.
//
// Signals of a block are interleaved: sample k of lane l is
// signal[k][l]. An effect's batched form runs the same operations as its
// scalar form on every lane (same order, no fused multiply-add: the build
// uses -ffp-contract=off), so each lane's output equals apply()'s bit for bit.
#include <Eigen/Core>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "framework/model/input_hold.hpp"

namespace hystbench {

#if defined(__AVX512F__)
inline constexpr int kEffectLanes = 8;
#elif defined(__AVX__)
inline constexpr int kEffectLanes = 4;
#else
inline constexpr int kEffectLanes = 2;
#endif

using LaneVector = double __attribute__((vector_size(kEffectLanes * sizeof(double))));
using LaneBits = std::int64_t __attribute__((vector_size(kEffectLanes * sizeof(double))));
using LaneMask = std::array<bool, kEffectLanes>;
// Parameters of each lane's candidate, in the effect's declared order.
using LaneParams = std::array<std::span<const double>, kEffectLanes>;

// |x| for a sample of one candidate or of a block, so that one template
// serves both forms of an effect.
inline double lane_abs(double x) { return std::abs(x); }
inline LaneVector lane_abs(LaneVector x) {
  return std::bit_cast<LaneVector>(std::bit_cast<LaneBits>(x) & std::numeric_limits<std::int64_t>::max());
}

inline bool lane_finite(double x, int /*lane*/ = 0) { return std::isfinite(x); }
inline bool lane_finite(LaneVector x, int lane) { return std::isfinite(x[lane]); }
// True when no lane is finite any more: a diverging block may stop early.
inline bool none_finite(double x) { return !std::isfinite(x); }
inline bool none_finite(LaneVector x) {
  for (int l = 0; l < kEffectLanes; ++l)
    if (std::isfinite(x[l])) return false;
  return true;
}

// What an effect's batched form sees besides its parameters and signal
// (the block version of SignalContext).
struct LaneContext {
  double sample_time = 0.0;
  const Eigen::VectorXd* time = nullptr;
  std::span<const LaneVector> stage_input;
  int substeps = 0;
  InputHold hold = InputHold::Spline;
};

// How an effect's parameters set it up, for one candidate.
enum class EffectSetup { Run, PassThrough, Invalid };

// Setup of effects with one coefficient that switches them off at 0
// (asymmetry's d2, drift's rate, creep's gamma): non-finite is invalid.
inline EffectSetup gain_like_setup(std::span<const double> p, std::array<double, 1>& c) {
  c = {p[0]};
  if (!std::isfinite(c[0])) return EffectSetup::Invalid;
  return c[0] == 0.0 ? EffectSetup::PassThrough : EffectSetup::Run;
}

// The batched form of an effect from its two scalar pieces: `setup(p, c)`
// turns one candidate's parameters into K coefficients (and says whether the
// effect runs, passes the signal through, or is invalid); `kernel(c)` runs
// the effect on the signal with lane-vector coefficients and returns its
// final state, whose lanes must be finite. Lanes that do not run keep their
// signal bit for bit; invalid lanes are cleared in ok.
template <std::size_t K, class Setup, class Kernel>
void run_lanes(const LaneParams& p, std::span<LaneVector> signal, LaneMask& ok, Setup setup, Kernel kernel) {
  std::array<LaneVector, K> coefficients{};
  LaneMask running{};
  bool any = false, all = true;
  for (int l = 0; l < kEffectLanes; ++l) {
    std::array<double, K> c{};
    const EffectSetup s = setup(p[l], c);
    if (s == EffectSetup::Invalid) ok[l] = false;
    if (s != EffectSetup::Run) {
      all = false;
      continue;
    }
    running[l] = any = true;
    for (std::size_t i = 0; i < K; ++i) coefficients[i][l] = c[i];
  }
  if (!any) return;
  std::vector<LaneVector> kept;
  if (!all) kept.assign(signal.begin(), signal.end());
  const LaneVector last = kernel(coefficients);
  for (int l = 0; l < kEffectLanes; ++l)
    if (running[l] && !std::isfinite(last[l])) ok[l] = false;
  if (all) return;
  LaneBits keep{};
  for (int l = 0; l < kEffectLanes; ++l) keep[l] = running[l] ? 0 : -1;
  for (std::size_t k = 0; k < signal.size(); ++k) signal[k] = keep ? kept[k] : signal[k];
}

}  // namespace hystbench
