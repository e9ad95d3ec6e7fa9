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
#include "framework/core/eigen.hpp"
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>

namespace hystbench {

// One vector register of the target. (Blocks of two or four registers were
// measured slower: GCC's code for the wider generic vectors costs more than
// the latency it hides.)
#if defined(__AVX512F__)
inline constexpr int kEffectLanes = 8;
#elif defined(__AVX__)
inline constexpr int kEffectLanes = 4;
#else
inline constexpr int kEffectLanes = 2;
#endif

using LaneVector = double __attribute__((vector_size(kEffectLanes * sizeof(double))));
// The lane-wise result of comparing two LaneVectors: 0 or -1 per lane.
using LaneBits = std::int64_t __attribute__((vector_size(kEffectLanes * sizeof(double))));
using LaneMask = std::array<bool, kEffectLanes>;
// Parameters of each lane's candidate, in the effect's declared order.
using LaneParams = std::array<std::span<const double>, kEffectLanes>;

// |x| for a sample of one candidate or of a block, so that one template
// serves both forms of an effect: the sign bit cleared, exactly as std::abs
// does for a double.
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

// One chunk of a block's record, as an effect's batched form sees it: the
// chunk starts at sample `begin`; `time` and `stage_input` are the chunk's
// own samples (the block version of SignalContext).
struct LaneChunk {
  Eigen::Index begin = 0;
  const double* time = nullptr;
  std::span<const LaneVector> stage_input;
};

// An effect running a block of candidates through a record a chunk of
// samples at a time, its state carried from one chunk to the next; the
// model runs every effect on a chunk before the next, so the block's
// signals stay in cache (Model::simulate_lanes).
class LaneRun {
 public:
  virtual ~LaneRun() = default;
  // The next chunk of the signal, in place.
  virtual void run(std::span<LaneVector> signal, const LaneChunk& chunk) = 0;
  // After the last chunk: clears ok[l] where the effect diverged.
  virtual void finish(LaneMask& ok) const = 0;
  // Whether run() reads chunk.stage_input (the model copies it only then).
  virtual bool reads_stage_input() const { return true; }
  // Whether run() needs the whole record as one chunk (an input spline
  // through every sample); the model then runs the record in one chunk.
  virtual bool whole_record() const { return false; }
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

// The K coefficients of every lane from `setup(p, c)`, which turns one
// candidate's parameters into K coefficients and says whether the effect
// runs, passes the signal through, or is invalid (then ok[l] is cleared).
template <std::size_t K>
struct LaneSetup {
  std::array<LaneVector, K> coefficients{};
  LaneMask running{};
  bool any = false, all = true;  // some lane runs; every lane runs

  template <class Setup>
  LaneSetup(const LaneParams& p, LaneMask& ok, Setup setup) {
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
  }

  // Lanes that do not run get back their samples from `kept`, bit for bit.
  void restore_idle(std::span<const LaneVector> kept, std::span<LaneVector> signal) const {
    LaneBits keep{};
    for (int l = 0; l < kEffectLanes; ++l) keep[l] = running[l] ? 0 : -1;
    for (std::size_t k = 0; k < signal.size(); ++k) signal[k] = keep ? kept[k] : signal[k];
  }
};

}  // namespace hystbench
