// Second-order discrete linear block with unit static gain (dynamics stage).
//
//   y[k] = b0·w[k] + b1·w[k-1] + b2·w[k-2] − a1·y[k-1] − a2·y[k-2],
//   b0 = 1 + a1 + a2 − b1 − b2   (so that H(1) = 1)
//
// from rest (w[k<0] = y[k<0] = 0). The seed's ARX block
// r1[k] = a·r[k-1] + b·r[k-2] − c·r1[k-1] − d·r1[k-2] is this block times the
// static gain (a + b)/(1 + c + d) with a1 = c, a2 = d, b0 = 0: its gain is
// left to the model's gain, which removes the seed's flat direction between
// the two. Unlike the seed form, all parameters 0 is an exact pass-through
// (b0 = 1), which is the neutral value. Poles outside the Jury triangle
// |a2| < 1, |a1| < 1 + a2 make apply false.
// At the neutral value itself the poles cancel the zeros (both at z = 0),
// so there a1 and b1 (and a2 and b2) first move the output along the same
// direction, 1 − z⁻¹ (and 1 − z⁻²); any second-order family through the
// pass-through has this, and it disappears as soon as the block does
// something. Away from neutral no direction is flat.
#include <cmath>

#include "framework/model/effect.hpp"

namespace hystbench {
namespace {

class Arx : public Effect {
 public:
  static EffectInfo info() {
    EffectInfo i;
    i.name = "arx";
    i.summary =
        "second-order discrete transfer function (b0 + b1 z⁻¹ + b2 z⁻²)/(1 + a1 z⁻¹ + a2 z⁻²), "
        "b0 fixed by unit static gain";
    i.citation =
        "Ljung, System Identification, 2nd ed., 1999; seed Hammerstein model (DESIGN.md §3)";
    i.stage = EffectStage::Dynamics;
    i.params = {
        {"a1", -2.0, 2.0, 0.0, 0, 0, "", "first denominator coefficient"},
        {"a2", -1.0, 1.0, 0.0, 0, 0, "", "second denominator coefficient"},
        {"b1", -2.0, 2.0, 0.0, 0, 0, "", "numerator coefficient of w[k-1]"},
        {"b2", -2.0, 2.0, 0.0, 0, 0, "", "numerator coefficient of w[k-2]"},
    };
    i.signature =
        "the error grows with the excitation frequency and the input-residual cross-correlation "
        "is significant at positive lags";
    return i;
  }

  bool apply(std::span<const double> p, const SignalContext&,
             Eigen::Ref<Eigen::VectorXd> signal) const override {
    const double a1 = p[0], a2 = p[1], b1 = p[2], b2 = p[3];
    for (double x : p)
      if (!std::isfinite(x)) return false;
    if (a1 == 0.0 && a2 == 0.0 && b1 == 0.0 && b2 == 0.0) return true;
    if (!(std::abs(a2) < 1.0 && std::abs(a1) < 1.0 + a2)) return false;
    const double b0 = (1.0 + a1 + a2) - (b1 + b2);
    double* s = signal.data();
    double w1 = 0.0, w2 = 0.0, y1 = 0.0, y2 = 0.0;
    for (Eigen::Index k = 0; k < signal.size(); ++k) {
      const double w = s[k];
      const double y = ((b0 * w + b1 * w1) + (b2 * w2 - a2 * y2)) - a1 * y1;
      s[k] = y;
      w2 = w1;
      w1 = w;
      y2 = y1;
      y1 = y;
    }
    return std::isfinite(y1);
  }
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_EFFECT(hystbench::Arx)
