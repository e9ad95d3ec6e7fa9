// Transport delay of the input by a fractional number of samples (input stage).
//
//   signal[k] = v(k − d),   d = n + f samples, n integer, 0 ≤ f < 1
//
// Between samples v is interpolated with a Catmull-Rom cubic through
// v[j-1], v[j], v[j+1], v[j+2] (j = k − n − 1, position t = 1 − f between v[j]
// and v[j+1]). The output is then continuous with a continuous derivative in
// d, so optimizers can move d smoothly; linear interpolation would put a kink
// at every integer d. The cubic's fourth point v[j+2] = v[k−n+1] lies in the
// future when n = 0; it is extrapolated linearly there (2·v[k] − v[k−1]),
// which keeps the delay causal, still reproduces a ramp exactly and changes
// neither the value nor the slope in d at integer d (its weight and the
// weight's slope vanish there).
// Samples before the record start are 0: the chain starts at rest with zero
// input (docs/models.md#hammerstein-seed-model), as the hysteresis and
// dynamics states do.
// Neutral d = 0 (exact pass-through). The delay is in samples, not seconds:
// a delay fitted at one sample rate means a different time at another.
#include <algorithm>
#include <cmath>
#include <array>
#include <deque>
#include <vector>

#include "framework/core/scratch_pool.hpp"
#include "framework/model/effect.hpp"
#include "framework/model/regressors.hpp"

namespace hystbench {
namespace {

// Signature statistic: corr(e, −dŷ/dt), with the lag of the largest
// input–residual cross-correlation. A measured output lagging the model by d
// seconds gives e = ŷ(t − d) − ŷ(t) ≈ −d·dŷ/dt, so the residual follows the
// negative model slope (least-squares d quoted), and r_ue peaks sharply at
// τ = d samples for a rough input (Ljung, System Identification, 1999, §16.6).
SignatureValue slope_correlation(const ResidualView& r) {
  const Eigen::VectorXd slope = -derivative(r.y_model, r.sample_time);
  const double energy = slope.squaredNorm();
  if (!(energy > 0)) return {};
  return {correlation(r.e, slope),
          {{"lag", peak_lag(r.ccf)}, {"seconds", r.e.dot(slope) / energy}}};
}

class Delay : public Effect {
 public:
  static EffectInfo info() {
    EffectInfo i;
    i.name = "delay";
    i.summary = "transport delay of the input by d samples (fractional, cubic interpolation)";
    i.citation =
        "Ljung, System Identification, 2nd ed., 1999 (input-residual cross-correlation); "
        "Catmull & Rom, Computer Aided Geometric Design, 1974 (interpolating spline)";
    i.stage = EffectStage::Input;
    i.params = {{"d", 0.0, 20.0, 0.0, 0, 0, "samples", "transport delay (0 = none)"}};
    i.signature =
        "the input-residual cross-correlation peaks at a non-zero lag and the error grows "
        "linearly with frequency, like −d·dy/dt";
    i.statistic = {"corr(e, −dŷ/dt)", slope_correlation,
                   "the residual follows −dŷ/dt (r = {value}; least-squares delay {seconds} s) "
                   "and the input-residual cross-correlation peaks at lag {lag} samples"};
    // At one frequency a delay is one phase lag, which a dynamic block's lag
    // matches; a delay's phase grows in proportion to frequency.
    i.rivals = {{"arx", ExcitationNeed::SeveralFrequencies}, {"msd", ExcitationNeed::SeveralFrequencies}};
    return i;
  }

  bool apply(std::span<const double> p, const SignalContext&,
             Eigen::Ref<Eigen::VectorXd> signal) const override {
    Weights c;
    const EffectSetup setup_result = setup(p, c);
    if (setup_result != EffectSetup::Run) return setup_result == EffectSetup::PassThrough;
    const Eigen::Index size = signal.size(), n = c.n;
    double* s = signal.data();
    // In place from the end: output k reads only samples at or before k.
    if (c.integer) {
      for (Eigen::Index k = size - 1; k >= 0; --k) s[k] = k >= n ? s[k - n] : 0.0;
      return true;
    }
    auto at = [s](Eigen::Index i) { return i >= 0 ? s[i] : 0.0; };
    const Eigen::Index first_full = std::min(size, n + 2);
    for (Eigen::Index k = size - 1; k >= first_full; --k) {
      const double* q = s + (k - n);
      s[k] = combine(c, q[-2], q[-1], q[0], q[c.ahead]);
    }
    for (Eigen::Index k = first_full - 1; k >= 0; --k) {
      const Eigen::Index j = k - n;
      s[k] = combine(c, at(j - 2), at(j - 1), at(j), at(j + c.ahead));
    }
    return true;
  }

  // Each lane has a delay of its own, so the block keeps the inputs seen so
  // far and every lane reads them at its own lag, through the same combine()
  // as apply().
  bool has_lanes() const override { return true; }
  std::unique_ptr<LaneRun> lane_run(const LaneParams& p, const LaneContext&, LaneMask& ok) const override {
    auto run = std::make_unique<DelayLanes>();
    for (int l = 0; l < kEffectLanes; ++l) {
      const EffectSetup s = setup(p[l], run->weights[l]);
      run->running[l] = s == EffectSetup::Run;
      if (s == EffectSetup::Invalid) ok[l] = false;
    }
    return run;
  }

  std::unique_ptr<EffectStepper> stepper(std::span<const double> p, const StepContext&) const override {
    Weights c;
    return stepper_for(setup(p, c), [&] {
      return kernel_stepper<History>([c](History& h, double v, double) { return sample(c, h, v); });
    });
  }

 private:
  // d = n + f; for f > 0 the Catmull-Rom weights of v[j-1], v[j], v[j+1],
  // v[j+2] (j = k − n − 1), the last point at index k − n + ahead.
  struct Weights {
    Eigen::Index n = 0;
    bool integer = true;
    double w0 = 0.0, w1 = 0.0, w2 = 0.0, w3 = 0.0;
    Eigen::Index ahead = 1;
  };

  static EffectSetup setup(std::span<const double> p, Weights& c) {
    const double d = p[0];
    // The upper limit keeps the integer part representable; any delay longer
    // than the record simply gives zeros.
    if (!std::isfinite(d) || d < 0.0 || d > 1e12) return EffectSetup::Invalid;
    if (d == 0.0) return EffectSetup::PassThrough;
    c.n = static_cast<Eigen::Index>(std::floor(d));
    const double f = d - double(c.n);
    c.integer = f == 0.0;
    const double t = 1.0 - f, t2 = t * t, t3 = t2 * t;
    c.w0 = 0.5 * (-t + 2.0 * t2 - t3);
    c.w1 = 0.5 * (2.0 - 5.0 * t2 + 3.0 * t3);
    c.w2 = 0.5 * (t + 4.0 * t2 - 3.0 * t3);
    c.w3 = 0.5 * (t3 - t2);
    if (c.n == 0) {
      // v[k+1] is not known yet: extrapolate it linearly, 2·v[k] − v[k−1].
      c.w2 += 2.0 * c.w3;
      c.w1 -= c.w3;
      c.w3 = 0.0;
      c.ahead = 0;
    }
    return EffectSetup::Run;
  }

  // One output from the inputs v[k−n−2], v[k−n−1], v[k−n], v[k−n+ahead]:
  // the batch and streaming forms both sum them in this order.
  static double combine(const Weights& c, double a, double b, double x, double e) {
    return ((c.w0 * a + c.w1 * b) + c.w2 * x) + c.w3 * e;
  }

  // The streaming form's memory: the last n + 3 inputs (fewer at the start).
  struct History {
    std::deque<double> v;
    Eigen::Index count = 0;  // inputs seen
    // Input j, 0 before the record (j must be one of the inputs kept).
    double at(Eigen::Index j) const {
      return j >= 0 ? v[std::size_t(j - (count - Eigen::Index(v.size())))] : 0.0;
    }
  };

  class DelayLanes final : public LaneRun {
   public:
    std::array<Weights, kEffectLanes> weights{};
    LaneMask running{};

    void run(std::span<LaneVector> signal, const LaneChunk& chunk) override {
      past_->insert(past_->end(), signal.begin(), signal.end());
      for (int l = 0; l < kEffectLanes; ++l) {
        if (!running[l]) continue;
        const Weights& c = weights[l];
        for (std::size_t i = 0; i < signal.size(); ++i) {
          const Eigen::Index j = chunk.begin + Eigen::Index(i) - c.n;  // k − n
          signal[i][l] = c.integer ? at(j, l) : combine(c, at(j - 2, l), at(j - 1, l), at(j, l), at(j + c.ahead, l));
        }
      }
    }
    void finish(LaneMask&) const override {}
    bool reads_stage_input() const override { return false; }

   private:
    // Input j of lane l, 0 before the record.
    double at(Eigen::Index j, int l) const { return j >= 0 ? (*past_)[std::size_t(j)][l] : 0.0; }
    // Every input of the block so far. Borrowed, so that its memory outlives
    // the block: grown afresh in every block it cost copies and page faults.
    using Inputs = std::vector<LaneVector>;
    static ScratchPool<Inputs>::Lease no_inputs() {
      static ScratchPool<Inputs> pool;
      auto inputs = pool.lend();
      inputs->clear();
      return inputs;
    }
    ScratchPool<Inputs>::Lease past_ = no_inputs();
  };

  static double sample(const Weights& c, History& h, double v) {
    h.v.push_back(v);
    if (Eigen::Index(h.v.size()) > c.n + 3) h.v.pop_front();
    const Eigen::Index j = h.count++ - c.n;  // k − n
    if (c.integer) return h.at(j);
    return combine(c, h.at(j - 2), h.at(j - 1), h.at(j), h.at(j + c.ahead));
  }
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_EFFECT(hystbench::Delay)
