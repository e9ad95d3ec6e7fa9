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
// input (docs/design.md#hammerstein-seed-model), as the hysteresis and
// dynamics states do.
// Neutral d = 0 (exact pass-through). The delay is in samples, not seconds:
// a delay fitted at one sample rate means a different time at another.
#include <algorithm>
#include <cmath>

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
    return i;
  }

  bool apply(std::span<const double> p, const SignalContext&,
             Eigen::Ref<Eigen::VectorXd> signal) const override {
    const double d = p[0];
    // The upper limit keeps the integer part representable; any delay longer
    // than the record simply gives zeros.
    if (!std::isfinite(d) || d < 0.0 || d > 1e12) return false;
    if (d == 0.0) return true;
    const Eigen::Index size = signal.size();
    const Eigen::Index n = static_cast<Eigen::Index>(std::floor(d));
    const double f = d - double(n);
    double* s = signal.data();
    // In place from the end: output k reads only samples at or before k.
    if (f == 0.0) {
      for (Eigen::Index k = size - 1; k >= 0; --k) s[k] = k >= n ? s[k - n] : 0.0;
      return true;
    }
    const double t = 1.0 - f, t2 = t * t, t3 = t2 * t;
    const double w0 = 0.5 * (-t + 2.0 * t2 - t3);
    double w1 = 0.5 * (2.0 - 5.0 * t2 + 3.0 * t3);
    double w2 = 0.5 * (t + 4.0 * t2 - 3.0 * t3);
    double w3 = 0.5 * (t3 - t2);
    Eigen::Index ahead = 1;  // index of the fourth point relative to k − n
    if (n == 0) {
      // v[k+1] is not known yet: extrapolate it linearly, 2·v[k] − v[k−1].
      w2 += 2.0 * w3;
      w1 -= w3;
      w3 = 0.0;
      ahead = 0;
    }
    auto at = [s](Eigen::Index i) { return i >= 0 ? s[i] : 0.0; };
    const Eigen::Index first_full = std::min(size, n + 2);
    for (Eigen::Index k = size - 1; k >= first_full; --k) {
      const double* q = s + (k - n);
      s[k] = ((w0 * q[-2] + w1 * q[-1]) + w2 * q[0]) + w3 * q[ahead];
    }
    for (Eigen::Index k = first_full - 1; k >= 0; --k) {
      const Eigen::Index j = k - n;
      s[k] = ((w0 * at(j - 2) + w1 * at(j - 1)) + w2 * at(j)) + w3 * at(j + ahead);
    }
    return true;
  }
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_EFFECT(hystbench::Delay)
