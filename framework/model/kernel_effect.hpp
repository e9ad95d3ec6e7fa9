#pragma once
// An effect written once, as a per-sample kernel, and given all three forms
// the framework asks of an effect: apply() for one candidate, lane_run()
// for a block of candidates in vector lanes, and stepper() for streaming.
// The three run the same kernel, so they agree bit for bit.
//
// The effect class D derives from KernelEffect<D, K, Drive> and supplies
//
//   static EffectSetup setup(std::span<const double> p, double Ts, std::array<double, K>& c);
//       its K coefficients from the parameters, and whether it runs
//   template <class V> struct State { ... };
//       the state at rest when value-initialised (the default: none)
//   template <class V> static V sample(const std::array<V, K>& c, const Aux& aux,
//                                      State<V>& state, V signal, Drive d);
//       one sample: what leaves the effect, given what enters it
//   template <class V> static V health(const std::array<V, K>& c, const State<V>& state);
//       a value that is finite unless the effect has diverged
//
// and, where needed, `static Aux aux(double Ts)` (constants of the sample
// time shared by every lane) and `kEarlyExit = true` (check health every
// 1024 samples and stop a diverged block early). V is double or LaneVector.
#include <array>
#include <cmath>
#include <memory>
#include <span>
#include <vector>

#include "framework/model/effect.hpp"

namespace hystbench {

// What drives an effect besides the signal through it: nothing, the stage
// input (SignalContext::stage_input), or time.
enum class EffectDrive { None, StageInput, Time };

template <class D, std::size_t K, EffectDrive Drive>
class KernelEffect : public Effect {
 public:
  bool apply(std::span<const double> p, const SignalContext& ctx,
             Eigen::Ref<Eigen::VectorXd> signal) const override {
    std::array<double, K> c;
    const EffectSetup s = D::setup(p, ctx.sample_time, c);
    if (s != EffectSetup::Run) return s == EffectSetup::PassThrough;
    if (!has_drive(ctx, signal.size())) return false;
    return std::isfinite(run_record(c, D::aux(ctx.sample_time), scalar_drive(ctx), signal.data(), signal.size()));
  }

  bool has_lanes() const override { return true; }
  std::unique_ptr<LaneRun> lane_run(const LaneParams& p, const LaneContext& ctx, LaneMask& ok) const override {
    return std::make_unique<KernelLaneRun>(p, ctx.sample_time, ok);
  }

  // In a stream, time is k·Ts at sample k, counted here; a record's time
  // column (from 0) equals it to rounding.
  std::unique_ptr<EffectStepper> stepper(std::span<const double> p, const StepContext& ctx) const override {
    std::array<double, K> c;
    return stepper_for(D::setup(p, ctx.sample_time, c), [&] {
      return kernel_stepper<StreamState>(
          [c, aux = D::aux(ctx.sample_time), ts = ctx.sample_time](StreamState& st, double signal,
                                                                   double stage_input) {
            if constexpr (Drive == EffectDrive::Time)
              return D::sample(c, aux, st.state, signal, ts * st.samples++);
            else
              return D::sample(c, aux, st.state, signal, stage_input);
          });
    });
  }

  // Defaults an effect replaces by declaring its own.
  struct NoAux {};
  static NoAux aux(double /*Ts*/) { return {}; }
  template <class V>
  struct State {};
  static constexpr bool kEarlyExit = false;

 private:
  struct StreamState {
    typename D::template State<double> state{};
    double samples = 0.0;
  };

  // Whether the context holds the drive for n samples.
  static bool has_drive(const SignalContext& ctx, Eigen::Index n) {
    if constexpr (Drive == EffectDrive::StageInput)
      return ctx.stage_input && ctx.stage_input->size() == n;
    else if constexpr (Drive == EffectDrive::Time)
      return ctx.time && ctx.time->size() == n;
    else
      return true;
  }

  static const double* scalar_drive(const SignalContext& ctx) {
    if constexpr (Drive == EffectDrive::StageInput)
      return ctx.stage_input->data();
    else if constexpr (Drive == EffectDrive::Time)
      return ctx.time->data();
    else
      return nullptr;
  }

  // A block of candidates, one per lane, its state carried across chunks.
  // Lanes that do not run keep their signal bit for bit.
  class KernelLaneRun final : public LaneRun {
   public:
    KernelLaneRun(const LaneParams& p, double Ts, LaneMask& ok)
        : setup_(p, ok, [Ts](std::span<const double> q, std::array<double, K>& c) {
            return D::setup(q, Ts, c);
          }),
          aux_(D::aux(Ts)) {}

    void run(std::span<LaneVector> signal, const LaneChunk& chunk) override {
      if constexpr (Drive == EffectDrive::Time) missing_time_ = missing_time_ || !chunk.time;
      if (!setup_.any || stopped_ || missing_time_) return;
      if (!setup_.all) kept_.assign(signal.begin(), signal.end());
      stopped_ = !advance(setup_.coefficients, aux_, state_, drive(chunk), signal.data(), chunk.begin,
                          Eigen::Index(signal.size()));
      if (!setup_.all) setup_.restore_idle(kept_, signal);
    }

    // As apply(): a running lane fails when it diverged or had no time axis.
    void finish(LaneMask& ok) const override {
      if (!setup_.any) return;
      const LaneVector last = D::health(setup_.coefficients, state_);
      for (int l = 0; l < kEffectLanes; ++l)
        if (setup_.running[l] && (missing_time_ || !std::isfinite(last[l]))) ok[l] = false;
    }

    bool reads_stage_input() const override { return Drive == EffectDrive::StageInput; }

   private:
    static auto drive(const LaneChunk& chunk) {
      if constexpr (Drive == EffectDrive::StageInput)
        return chunk.stage_input.data();
      else
        return chunk.time;  // time, or unused
    }

    LaneSetup<K> setup_;
    decltype(D::aux(0.0)) aux_;
    typename D::template State<LaneVector> state_{};
    std::vector<LaneVector> kept_;
    bool stopped_ = false;  // every running lane diverged: the rest is skipped
    bool missing_time_ = false;  // the data have no time axis
  };

  // Samples [first, first + n) of one candidate (V = double) or a block
  // (V = LaneVector), s and drive pointing at sample `first`. Returns false
  // when the effect stopped early because every lane diverged.
  template <class V, class Aux, class S, class In>
  static bool advance(const std::array<V, K>& coefficients, const Aux& aux, S& carried, const In* drive, V* s,
                      Eigen::Index first, Eigen::Index n) {
    // Local copies: the signal cannot alias them, so the recurrence's state
    // stays in registers instead of being stored and reloaded every sample.
    const std::array<V, K> c = coefficients;
    S state = carried;
    for (Eigen::Index k = 0; k < n; ++k) {
      if constexpr (Drive == EffectDrive::None)
        s[k] = D::sample(c, aux, state, s[k], 0.0);
      else
        s[k] = D::sample(c, aux, state, s[k], drive[k]);
      // A non-finite state stays non-finite; checking now and then (at the
      // same samples of the record, whatever the chunks) ends a diverging
      // run early without a test on every sample.
      if constexpr (D::kEarlyExit)
        if (((first + k) & 1023) == 1023 && none_finite(D::health(c, state))) {
          carried = state;
          return false;
        }
    }
    carried = state;
    return true;
  }

  // The whole record of one candidate; returns health.
  template <class Aux>
  static double run_record(const std::array<double, K>& c, const Aux& aux, const double* drive, double* s,
                           Eigen::Index n) {
    typename D::template State<double> state{};
    advance(c, aux, state, drive, s, 0, n);
    return D::health(c, state);
  }
};

}  // namespace hystbench
