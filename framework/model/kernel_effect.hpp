#pragma once
// An effect written once, as a per-sample kernel, and given all three forms
// the framework asks of an effect: apply() for one candidate, apply_lanes()
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
    const double* drive = scalar_drive(ctx, signal.size());
    if (Drive != EffectDrive::None && !drive) return false;
    return std::isfinite(run(c, D::aux(ctx.sample_time), drive, signal.data(), signal.size()));
  }

  bool has_lanes() const override { return true; }
  void apply_lanes(const LaneParams& p, const LaneContext& ctx, std::span<LaneVector> signal,
                   LaneMask& ok) const override {
    const auto* drive = lane_drive(ctx, signal.size());
    if (Drive != EffectDrive::None && !drive) return ok.fill(false);
    const auto setup = [&](std::span<const double> q, std::array<double, K>& c) {
      return D::setup(q, ctx.sample_time, c);
    };
    run_lanes<K>(p, signal, ok, setup, [&](const std::array<LaneVector, K>& c) {
      return run(c, D::aux(ctx.sample_time), drive, signal.data(), Eigen::Index(signal.size()));
    });
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

  static const double* scalar_drive(const SignalContext& ctx, Eigen::Index n) {
    if constexpr (Drive == EffectDrive::StageInput)
      return ctx.stage_input && ctx.stage_input->size() == n ? ctx.stage_input->data() : nullptr;
    else if constexpr (Drive == EffectDrive::Time)
      return ctx.time && ctx.time->size() == n ? ctx.time->data() : nullptr;
    else
      return nullptr;
  }

  // The stage input is a block signal (one value per lane), time one column.
  static auto lane_drive(const LaneContext& ctx, std::size_t n) {
    if constexpr (Drive == EffectDrive::StageInput)
      return ctx.stage_input.size() == n ? ctx.stage_input.data() : nullptr;
    else if constexpr (Drive == EffectDrive::Time)
      return ctx.time && std::size_t(ctx.time->size()) == n ? ctx.time->data() : nullptr;
    else
      return static_cast<const double*>(nullptr);
  }

  // One candidate (V = double) or a block (V = LaneVector); returns health.
  template <class V, class Aux, class In>
  static V run(const std::array<V, K>& c, const Aux& aux, const In* drive, V* s, Eigen::Index n) {
    typename D::template State<V> state{};
    for (Eigen::Index k = 0; k < n; ++k) {
      if constexpr (Drive == EffectDrive::None)
        s[k] = D::sample(c, aux, state, s[k], 0.0);
      else
        s[k] = D::sample(c, aux, state, s[k], drive[k]);
      // A non-finite state stays non-finite; checking now and then ends a
      // diverging run early without a test on every sample.
      if constexpr (D::kEarlyExit)
        if ((k & 1023) == 1023 && none_finite(D::health(c, state))) break;
    }
    return D::health(c, state);
  }
};

}  // namespace hystbench
