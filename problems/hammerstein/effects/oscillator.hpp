#pragma once
// A mass-spring-damper whose restoring force a law sets, integrated in
// continuous time (the effects feedback_hysteresis and duffing):
//
//   y''/wn^2 + 2 zeta y'/wn + f(y, y'/wn, z) = w,   z' = g(y, y', z),
//
// in normalised units, with unit static gain at small amplitude. Its first
// two parameters are the natural period (0 = infinitely stiff: the effect
// passes its input through exactly, which makes it neutral when added to a
// model without msd) and the damping ratio, named as msd's so that a law
// that extends msd starts from msd's resonance. The law supplies f, g and
// the meaning of the parameters after those two; a law without an internal
// state keeps z at 0.
//
// Integration: classical RK4 with `substeps` steps per sample (by default as
// many as keep the fastest linear mode within kStepAngle per step, at most
// 20; raised when the oscillator is too stiff for the step, up to 2000, or
// up to ten times a fixed count, beyond which the parameters fail), the
// input reconstructed between samples by the model's input hold
// (input_hold.hpp): by default a not-a-knot cubic spline through the record,
// or a windowed sinc (band-limited) for an input that reaches towards the
// Nyquist frequency; linear or zero-order hold in a stream, where output k
// may depend on inputs up to k only. For a law whose force has
// kinks (|y'|, |z|), a step in which the velocity or z changes sign is split
// at the crossing. The state starts at rest (y = y' = z = 0) and output 0 is
// 0; output k + 1 is the state after the interval from sample k to k + 1.
//
// A law is a class with
//   static EffectInfo info();   // params: oscillator_params(the law's own)
//   static std::optional<OscillatorLaw> coefficients(std::span<const double> law_params, double ws);
//   template <class V> static V excess(const OscillatorRates<V>&, V w, V y, V v, V z);  // w − f(y, v, z)
//   template <class V> static V zdot(const OscillatorRates<V>&, V y, V v, V z);   // g
// and an effect file registers HYSTBENCH_EFFECT(hystbench::Oscillator<Law>).
// The one-candidate, block and streaming forms all run the same law code,
// so each lane of a block is bit for bit its candidate.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <span>
#include <vector>

#include "framework/core/scratch_pool.hpp"
#include "framework/model/band_limited_interpolation.hpp"
#include "framework/model/effect.hpp"
#include "framework/model/input_hold.hpp"
#include "framework/model/input_interpolation.hpp"

namespace hystbench {

// The oscillator in time units of samples, for one candidate (V = double)
// or a block of candidates (V = LaneVector): ω² and 2ζω (ω = ωn·Ts rad per
// sample), and the law's three coefficients.
template <class V>
struct OscillatorRates {
  V w2, c1;
  V p0, p1, p2;
};

// What a law makes of its parameters: its coefficients, the factor by which
// it stiffens the linear spring over the amplitudes it is expected to meet
// (it sizes the sub-steps), and whether its force has kinks.
struct OscillatorLaw {
  std::array<double, 3> p{};
  double stiffening = 1.0;
  bool kinks = false;
};

// The parameters every law starts with, then `own`: the natural period of
// the linear part and the damping ratio, as msd names them.
inline std::vector<EffectParam> oscillator_params(std::vector<EffectParam> own) {
  std::vector<EffectParam> p = {
      {"period", 0.0, 0.2, 0.0, 0, 0, "s",
       "natural period 2 pi sqrt(m/k) of the linear part (0 = infinitely stiff: pass-through)"},
      {"zeta", 1e-3, 2.0, 0.5, 0, 0, "", "damping ratio c/(2 sqrt(k m))"},
  };
  p.insert(p.end(), own.begin(), own.end());
  return p;
}

template <class Law>
class Oscillator : public Effect {
 public:
  static EffectInfo info() { return Law::info(); }

  bool apply(std::span<const double> p, const SignalContext& ctx,
             Eigen::Ref<Eigen::VectorXd> signal) const override {
    Coefficients c;
    const EffectSetup s = setup(p, ctx.sample_time, ctx.substeps, c);
    if (s != EffectSetup::Run) return s == EffectSetup::PassThrough;
    if (signal.size() == 0) return true;
    return run_record(c, ctx.hold, signal);
  }

  bool has_lanes() const override { return true; }
  std::unique_ptr<LaneRun> lane_run(const LaneParams& p, const LaneContext& ctx, LaneMask& ok) const override {
    return std::make_unique<Block>(p, ctx, ok);
  }

  std::unique_ptr<EffectStepper> stepper(std::span<const double> p, const StepContext& ctx) const override {
    Coefficients c;
    if (!is_causal(ctx.hold)) return nullptr;  // the spline and the sinc need the whole record
    return stepper_for(setup(p, ctx.sample_time, ctx.substeps, c), [&] {
      return kernel_stepper<Stream>(
          [c, hold = ctx.hold](Stream& st, double w, double) { return sample(c, hold, st, w); });
    });
  }

 private:
  // By default a sub-step turns the fastest linear mode by at most kStepAngle
  // radians. RK4's largest error, against 200 sub-steps, is then 5e-6 of the
  // output's RMS on the hidden-effect oscillator (4 sub-steps) and 5e-5 with a
  // strong loop, whose z moves faster than the linear modes (3 sub-steps,
  // tests/feedback_hysteresis_test.cpp): below the noise of the quietest
  // record we know, Silverbox's 5e-4. More than kDefaultSubsteps are only
  // taken when the oscillator is stiff (more than 1 rad per step).
  static constexpr double kStepAngle = 0.1;
  static constexpr int kDefaultSubsteps = 20;
  static constexpr int kMaxSubsteps = 2000;
  // A fixed count (--substeps, or the coarse problem a global search runs on)
  // is a request for speed: a stiff oscillator is raised to at most
  // kFixedRaise times it and refused beyond. A global search's population
  // strays into oscillators far stiffer than the record resolves, and raising
  // them towards kMaxSubsteps made one Silverbox restart eight times slower
  // than its siblings (docs/discovery.md, "Measured benchmarks").
  static constexpr int kFixedRaise = 10;
  // A state beyond this (normalised units: the measured output has RMS 1) has
  // diverged.
  static constexpr double kDivergence = 1e6;

  template <class V>
  using Rates = OscillatorRates<V>;

  // One candidate's oscillator and its integration steps.
  struct Coefficients {
    Rates<double> r;
    int sub;          // RK4 steps per sample
    double h;         // their length, 1/sub
    bool kinks;       // the law's force has kinks where y' or z changes sign
  };

  // State (y, v = dy/dsample, z).
  template <class V>
  struct StateOf {
    V y{}, v{}, z{};
  };
  using State = StateOf<double>;

  static EffectSetup setup(std::span<const double> p, double ts, int substeps, Coefficients& c) {
    const double period = p[0], zeta = p[1];
    if (period == 0.0) return EffectSetup::PassThrough;
    const double fn = 1.0 / period;
    if (!(period > 0.0) || !std::isfinite(fn) || !(zeta > 0.0) || !std::isfinite(zeta) || !(ts > 0.0))
      return EffectSetup::Invalid;
    // Time in samples: w_s = wn * Ts rad per sample. A law whose force
    // depends on the velocity needs it to convert y'/wn into samples.
    const double ws = 2.0 * std::numbers::pi * fn * ts;
    const std::optional<OscillatorLaw> law = Law::coefficients(p.subspan(2), ws);
    if (!law) return EffectSetup::Invalid;
    // Largest eigenvalue modulus of the linearised system, bounded by
    // ws_eff (zeta + sqrt(zeta^2 + 1)); keep |lambda| h <= 1.
    const double stiff = ws * std::sqrt(law->stiffening) * (zeta + std::sqrt(zeta * zeta + 1.0));
    int sub = substeps > 0 ? substeps : std::clamp(int(std::ceil(stiff / kStepAngle)), 1, kDefaultSubsteps);
    if (stiff > double(sub)) {
      const int most = substeps > 0 ? std::min(kMaxSubsteps, kFixedRaise * substeps) : kMaxSubsteps;
      if (!(stiff <= double(most))) return EffectSetup::Invalid;
      sub = static_cast<int>(std::ceil(stiff));
    }
    c = {{ws * ws, 2.0 * zeta * ws, law->p[0], law->p[1], law->p[2]}, sub, 1.0 / sub, law->kinks};
    return EffectSetup::Run;
  }

  // One RK4 step of length `step` with the input at its start, middle and
  // end. The one-candidate and the block forms run these same operations,
  // so each lane of a block is bit for bit its candidate.
  template <class V>
  static StateOf<V> rk4(const Rates<V>& c, const StateOf<V>& s, V wa, V wm, V wb, double step) {
    const V w2 = c.w2, c1 = c.c1;
    const double half = 0.5 * step, sixth = step / 6.0;
    const V k1y = s.v, k1v = w2 * Law::excess(c, wa, s.y, s.v, s.z) - c1 * s.v, k1z = Law::zdot(c, s.y, s.v, s.z);
    const V y2 = s.y + half * k1y, v2 = s.v + half * k1v, z2 = s.z + half * k1z;
    const V k2y = v2, k2v = w2 * Law::excess(c, wm, y2, v2, z2) - c1 * v2, k2z = Law::zdot(c, y2, v2, z2);
    const V y3 = s.y + half * k2y, v3 = s.v + half * k2v, z3 = s.z + half * k2z;
    const V k3y = v3, k3v = w2 * Law::excess(c, wm, y3, v3, z3) - c1 * v3, k3z = Law::zdot(c, y3, v3, z3);
    const V y4 = s.y + step * k3y, v4 = s.v + step * k3v, z4 = s.z + step * k3z;
    const V k4y = v4, k4v = w2 * Law::excess(c, wb, y4, v4, z4) - c1 * v4, k4z = Law::zdot(c, y4, v4, z4);
    return StateOf<V>{s.y + sixth * (k1y + 2.0 * (k2y + k3y) + k4y),
                      s.v + sixth * (k1v + 2.0 * (k2v + k3v) + k4v),
                      s.z + sixth * (k1z + 2.0 * (k2z + k3z) + k4z)};
  }

  // A law with |v| or |z| in it has kinks where v or z changes sign
  // (velocity reversals, zero crossings of the hysteretic force); RK4 loses
  // its order over a step containing one (error O(h^2) per event).
  static bool has_kink(const Coefficients& c, const State& x, const State& next) {
    return c.kinks && (x.v * next.v < 0.0 || x.z * next.z < 0.0);
  }

  // Sub-step i from x again, split at the crossing (located by linear
  // interpolation between x and the unsplit step's end, next).
  template <class InputAt>
  static State split_step(const Coefficients& c, const State& x, const State& next, int i, double w_start,
                          double w_end, InputAt w_at) {
    double theta = 1.0;
    if (x.v * next.v < 0.0) theta = std::min(theta, x.v / (x.v - next.v));
    if (x.z * next.z < 0.0) theta = std::min(theta, x.z / (x.z - next.z));
    theta = std::clamp(theta, 1e-3, 1.0 - 1e-3);
    auto at = [&](double frac) { return w_at((double(i) + frac) * c.h); };  // frac of this sub-step
    const State mid = rk4(c.r, x, w_start, at(0.5 * theta), at(theta), theta * c.h);
    return rk4(c.r, mid, at(theta), at(0.5 * (1.0 + theta)), w_end, (1.0 - theta) * c.h);
  }

  // Advances x over one sample interval, shared by the batch and streaming
  // forms under every hold: wv[j] is the input at fraction j/(2 sub) of the
  // interval (j = 0 .. 2 sub), w_at(s) the input at any fraction s.
  template <class InputAt>
  static void advance(const Coefficients& c, State& x, const double* wv, InputAt w_at) {
    for (int i = 0; i < c.sub; ++i) {
      State next = rk4(c.r, x, wv[2 * i], wv[2 * i + 1], wv[2 * i + 2], c.h);
      if (has_kink(c, x, next)) next = split_step(c, x, next, i, wv[2 * i], wv[2 * i + 2], w_at);
      x = next;
    }
  }

  // Also true for NaN.
  static bool diverged(const State& x) {
    return !(std::abs(x.y) < kDivergence && std::abs(x.z) < kDivergence && std::abs(x.v) < kDivergence);
  }

  // The input on the interval from w0 to w1 under a causal hold, at the
  // fractions advance() reads.
  static void fill_held(const Coefficients& c, InputHold hold, double w0, double w1, std::vector<double>& wv) {
    wv.resize(2 * c.sub + 1);
    for (int j = 0; j <= 2 * c.sub; ++j) wv[j] = held_value(hold, w0, w1, double(j) / double(2 * c.sub));
  }

  // One candidate's whole record, in place; false when it diverged.
  static bool run_record(const Coefficients& c, InputHold hold, Eigen::Ref<Eigen::VectorXd> signal) {
    return is_causal(hold) ? run_held(c, hold, signal) : run_whole_record(c, hold, signal);
  }

  // An interpolant's weights at the fractions j/(2 sub) that advance() reads.
  template <class Weights>
  static void fraction_weights(int sub, Weights (*of)(double), std::vector<Weights>& weights) {
    weights.resize(std::size_t(2 * sub + 1));
    for (int j = 0; j <= 2 * sub; ++j) weights[std::size_t(j)] = of(double(j) / double(2 * sub));
  }

  // Batch form under a hold through the whole record (not causal): at(k, j)
  // is the input at fraction j/(2 sub) of the interval from sample k,
  // between(k, s) at any fraction s.
  template <class At, class Between>
  static bool run_whole(const Coefficients& c, Eigen::Ref<Eigen::VectorXd> signal, At at, Between between) {
    thread_local std::vector<double> wv;
    wv.resize(std::size_t(2 * c.sub + 1));
    State x;
    signal[0] = 0.0;
    for (Eigen::Index k = 0; k + 1 < signal.size(); ++k) {
      for (int j = 0; j <= 2 * c.sub; ++j) wv[std::size_t(j)] = at(k, j);
      advance(c, x, wv.data(), [&](double s) { return between(k, s); });
      if (diverged(x)) return false;
      signal[k + 1] = x.y;
    }
    return true;
  }

  // The spline, or under the band-limited hold the windowed sinc where it
  // reaches (the spline near the ends). The kernel reads samples ahead of
  // the one being overwritten: it reads a copy of the input.
  static bool run_whole_record(const Coefficients& c, InputHold hold, Eigen::Ref<Eigen::VectorXd> signal) {
    thread_local UniformCubicSpline spline;
    thread_local std::vector<UniformCubicSpline::Weights> weights;
    thread_local std::vector<double> input;
    thread_local std::vector<BandLimitedKernel::Weights> kernels;
    spline.fit(signal);
    fraction_weights(c.sub, &UniformCubicSpline::weights, weights);
    const bool sinc = hold == InputHold::Bandlimited;
    if (sinc) {
      input.assign(signal.begin(), signal.end());
      fraction_weights(c.sub, &BandLimitedKernel::weights, kernels);
    }
    const std::span<const double> w(input);
    const auto by_sinc = [&](Eigen::Index k) { return sinc && BandLimitedKernel::reaches(k, w.size()); };
    return run_whole(
        c, signal,
        [&](Eigen::Index k, int j) {
          return by_sinc(k) ? BandLimitedKernel::value(w, k, kernels[std::size_t(j)])
                            : spline.value(k, weights[std::size_t(j)]);
        },
        [&](Eigen::Index k, double s) {
          return by_sinc(k) ? BandLimitedKernel::value(w, k, BandLimitedKernel::weights(s))
                            : spline.value(k, UniformCubicSpline::weights(s));
        });
  }

  // Batch form under a causal hold: the interval from sample k to k + 1 sees
  // those two samples only, exactly as the stream does.
  static bool run_held(const Coefficients& c, InputHold hold, Eigen::Ref<Eigen::VectorXd> signal) {
    thread_local std::vector<double> wv;
    State x;
    double w0 = signal[0];
    signal[0] = 0.0;
    for (Eigen::Index k = 0; k + 1 < signal.size(); ++k) {
      const double w1 = signal[k + 1];
      fill_held(c, hold, w0, w1, wv);
      advance(c, x, wv.data(), [&](double s) { return held_value(hold, w0, w1, s); });
      if (diverged(x)) return false;
      signal[k + 1] = x.y;
      w0 = w1;
    }
    return true;
  }

  // A block of candidates, run over the whole record at once (the spline
  // and band-limited holds need every sample before the first step). Lanes
  // that share a sub-step count advance together, one group after another,
  // and a lane whose sub-step has a kink redoes it alone with split_step();
  // a lane whose count no other lane has runs the one-candidate form.
  // Either way every lane is bit for bit what apply() gives its candidate.
  class Block final : public LaneRun {
   public:
    Block(const LaneParams& p, const LaneContext& ctx, LaneMask& ok) : hold_(ctx.hold) {
      for (int l = 0; l < kEffectLanes; ++l) {
        const EffectSetup s = setup(p[l], ctx.sample_time, ctx.substeps, c_[l]);
        if (s == EffectSetup::Invalid) ok[l] = false;
        running_[l] = s == EffectSetup::Run;
      }
    }

    void run(std::span<LaneVector> signal, [[maybe_unused]] const LaneChunk& chunk) override {
      eigen_assert(chunk.begin == 0 && "whole_record(): the record comes in one chunk");
      const std::array<LaneMask, kEffectLanes> groups = sub_step_groups();
      bool input_read = false;  // every group reads the block's input, not an earlier group's output
      for (int l = 0; l < kEffectLanes; ++l) {
        const int members = int(std::count(groups[l].begin(), groups[l].end(), true));
        if (members == 1) run_alone(l, signal);
        if (members < 2) continue;
        if (!input_read) read_input(signal), input_read = true;
        group_ = groups[l], sub_ = c_[l].sub;
        run_together(signal);
      }
    }

    void finish(LaneMask& ok) const override {
      for (int l = 0; l < kEffectLanes; ++l)
        if (failed_[l]) ok[l] = false;
    }
    bool reads_stage_input() const override { return false; }
    bool whole_record() const override { return true; }

   private:
    // Lane l through apply()'s own code.
    void run_alone(int l, std::span<LaneVector> signal) {
      Eigen::VectorXd x(Eigen::Index(signal.size()));
      for (Eigen::Index k = 0; k < x.size(); ++k) x[k] = signal[std::size_t(k)][l];
      failed_[l] = !run_record(c_[l], hold_, x);
      for (Eigen::Index k = 0; k < x.size(); ++k) signal[std::size_t(k)][l] = x[k];
    }

    // groups[l]: the running lanes with lane l's sub-step count, for the
    // first lane of each count; empty for the others.
    std::array<LaneMask, kEffectLanes> sub_step_groups() const {
      std::array<LaneMask, kEffectLanes> groups{};
      LaneMask placed{};
      for (int l = 0; l < kEffectLanes; ++l) {
        if (!running_[l] || placed[l]) continue;
        for (int m = l; m < kEffectLanes; ++m)
          if (running_[m] && c_[m].sub == c_[l].sub) groups[l][m] = placed[m] = true;
      }
      return groups;
    }

    void read_input(std::span<const LaneVector> signal);
    void run_together(std::span<LaneVector> signal);
    double whole_record_value(std::span<const LaneVector> input, Eigen::Index k, int l, double s) const;
    void fill_inputs(std::span<const LaneVector> input, Eigen::Index k, std::vector<LaneVector>& wv) const;
    void redo_kinks(const StateOf<LaneVector>& x, StateOf<LaneVector>& next, int i, Eigen::Index k,
                    const std::vector<LaneVector>& wv, std::span<const LaneVector> input) const;
    bool check_divergence(const StateOf<LaneVector>& x);

    // Record-long buffers, reused from one block to the next: a fit runs
    // thousands of blocks, and fresh megabyte buffers for each cost about
    // as much in page faults as the coarse integration itself. A block
    // fills them before it reads them.
    struct Scratch {
      std::vector<LaneVector> input;
      std::vector<LaneVector> second;  // the splines' second derivatives
      std::vector<double> super;       // the spline solve's scratch
      std::vector<UniformCubicSpline::Weights> weights;
      std::vector<BandLimitedKernel::Weights> kernels;
    };
    static ScratchPool<Scratch>& scratch() {
      static ScratchPool<Scratch> pool;
      return pool;
    }

    InputHold hold_;
    std::array<Coefficients, kEffectLanes> c_{};
    LaneMask running_{}, failed_{};
    LaneMask group_{};  // the lanes run_together() advances, and their
    int sub_ = 0;       // sub-step count
    ScratchPool<Scratch>::Lease lease_ = scratch().lend();
    Scratch& s_ = *lease_;
  };

  // The streaming form's state: the oscillator and the previous input.
  struct Stream {
    State x;
    double w_prev = 0.0;
    bool started = false;
    std::vector<double> wv;
  };

  // Sample k of the stream: integrates the interval from k − 1 to k.
  static double sample(const Coefficients& c, InputHold hold, Stream& st, double w) {
    if (!st.started) {  // output 0 is the state at rest
      st.started = true;
      st.w_prev = w;
      return 0.0;
    }
    const double w0 = st.w_prev;
    fill_held(c, hold, w0, w, st.wv);
    advance(c, st.x, st.wv.data(), [&](double s) { return held_value(hold, w0, w, s); });
    st.w_prev = w;
    return diverged(st.x) ? std::numeric_limits<double>::quiet_NaN() : st.x.y;
  }
};

// The block's input, and under the spline and band-limited holds every
// lane's spline.
template <class Law>
void Oscillator<Law>::Block::read_input(std::span<const LaneVector> signal) {
  s_.input.assign(signal.begin(), signal.end());
  if (is_causal(hold_)) return;
  s_.second.resize(s_.input.size());
  spline_second_derivatives<LaneVector>(s_.input, s_.second, s_.super);
}

// The lanes of group_ over the whole record, from read_input()'s input.
template <class Law>
void Oscillator<Law>::Block::run_together(std::span<LaneVector> signal) {
  const std::span<const LaneVector> input(s_.input);
  if (!is_causal(hold_)) fraction_weights(sub_, &UniformCubicSpline::weights, s_.weights);
  if (hold_ == InputHold::Bandlimited) fraction_weights(sub_, &BandLimitedKernel::weights, s_.kernels);
  Rates<LaneVector> r{};
  LaneBits keep{};  // lanes outside the group keep their signal
  for (int l = 0; l < kEffectLanes; ++l) {
    keep[l] = group_[l] ? 0 : -1;
    if (!group_[l]) continue;
    r.w2[l] = c_[l].r.w2, r.c1[l] = c_[l].r.c1, r.p0[l] = c_[l].r.p0, r.p1[l] = c_[l].r.p1, r.p2[l] = c_[l].r.p2;
  }
  const double h = 1.0 / sub_;
  std::vector<LaneVector> wv(std::size_t(2 * sub_ + 1));
  StateOf<LaneVector> x{};
  signal[0] = keep ? signal[0] : LaneVector{};
  for (Eigen::Index k = 0; k + 1 < Eigen::Index(signal.size()); ++k) {
    fill_inputs(input, k, wv);
    for (int i = 0; i < sub_; ++i) {
      StateOf<LaneVector> next = rk4(r, x, wv[2 * i], wv[2 * i + 1], wv[2 * i + 2], h);
      redo_kinks(x, next, i, k, wv, input);
      x = next;
    }
    if (!check_divergence(x)) return;
    signal[std::size_t(k + 1)] = keep ? signal[std::size_t(k + 1)] : x.y;
  }
}

// Lane l's input at position k + s under the spline or the band-limited
// hold, as UniformCubicSpline::value and BandLimitedKernel::value compute it.
template <class Law>
double Oscillator<Law>::Block::whole_record_value(std::span<const LaneVector> input, Eigen::Index k, int l,
                                                     double s) const {
  if (hold_ == InputHold::Bandlimited && BandLimitedKernel::reaches(k, input.size()))
    return BandLimitedKernel::value(input, k, BandLimitedKernel::weights(s))[l];
  const auto last = Eigen::Index(input.size()) - 1;
  if (k >= last) return input[std::size_t(last)][l];
  const auto i = std::size_t(k);
  return UniformCubicSpline::blend(UniformCubicSpline::weights(s), input[i][l], input[i + 1][l],
                                   s_.second[i][l], s_.second[i + 1][l]);
}

// The input of every lane at the fractions advance() reads, computed as
// UniformCubicSpline::value, BandLimitedKernel::value and held_value
// compute them.
template <class Law>
void Oscillator<Law>::Block::fill_inputs(std::span<const LaneVector> input, Eigen::Index k,
                                            std::vector<LaneVector>& wv) const {
  const LaneVector w0 = input[std::size_t(k)], w1 = input[std::size_t(k + 1)];
  const bool sinc = hold_ == InputHold::Bandlimited && BandLimitedKernel::reaches(k, input.size());
  for (int j = 0; j <= 2 * sub_; ++j) {
    if (sinc) {
      wv[std::size_t(j)] = BandLimitedKernel::value(input, k, s_.kernels[std::size_t(j)]);
    } else if (!is_causal(hold_)) {
      wv[std::size_t(j)] = UniformCubicSpline::blend(s_.weights[std::size_t(j)], w0, w1, s_.second[std::size_t(k)],
                                                     s_.second[std::size_t(k + 1)]);
    } else {
      wv[std::size_t(j)] = hold_ == InputHold::Zoh ? w0 : w0 + double(j) / double(2 * sub_) * (w1 - w0);
    }
  }
}

template <class Law>
void Oscillator<Law>::Block::redo_kinks(const StateOf<LaneVector>& x, StateOf<LaneVector>& next, int i,
                                           Eigen::Index k, const std::vector<LaneVector>& wv,
                                           std::span<const LaneVector> input) const {
  const LaneBits crossing = (x.v * next.v < 0.0) | (x.z * next.z < 0.0);
  for (int l = 0; l < kEffectLanes; ++l) {
    if (!crossing[l] || !group_[l] || failed_[l]) continue;
    const State from{x.y[l], x.v[l], x.z[l]}, to{next.y[l], next.v[l], next.z[l]};
    if (!has_kink(c_[l], from, to)) continue;
    const auto w_at = [&](double s) {
      if (!is_causal(hold_)) return whole_record_value(input, k, l, s);
      return held_value(hold_, input[std::size_t(k)][l], input[std::size_t(k + 1)][l], s);
    };
    const double w_start = wv[std::size_t(2 * i)][l], w_end = wv[std::size_t(2 * i + 2)][l];
    const State redone = split_step(c_[l], from, to, i, w_start, w_end, w_at);
    next.y[l] = redone.y, next.v[l] = redone.v, next.z[l] = redone.z;
  }
}

// Marks the group's lanes that diverged in this sample, as apply() stops
// there; false once every lane of the group has.
template <class Law>
bool Oscillator<Law>::Block::check_divergence(const StateOf<LaneVector>& x) {
  bool any_left = false;
  for (int l = 0; l < kEffectLanes; ++l) {
    if (!group_[l] || failed_[l]) continue;
    failed_[l] = diverged(State{x.y[l], x.v[l], x.z[l]});
    any_left = any_left || !failed_[l];
  }
  return any_left;
}

}  // namespace hystbench
