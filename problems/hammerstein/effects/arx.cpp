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
#include <array>
#include <cmath>

#include "framework/model/kernel_effect.hpp"
#include "framework/model/regressors.hpp"
#include "problems/hammerstein/effects/biquad.hpp"

namespace hystbench {
namespace {

// Signature statistic: the share of the residual that an ARX correction of
// the model output explains beyond the residual's own past: with
// A(z) = 1 + a1 z⁻¹ + a2 z⁻², a missing block B(z)/A(z) leaves e = (B/A − 1)·ŷ,
// that is A·e = (B − A)·ŷ, so
//   e[k] = −a1·e[k−1] − a2·e[k−2] + c0·ŷ[k] + c1·ŷ[k−1] + c2·ŷ[k−2].
// The statistic is the partial R² of the ŷ terms given e[k−1], e[k−2]:
// (SSE of the AR fit − SSE of the ARX fit) / SSE of the AR fit. Conditioning on
// the residual's own past prewhitens it, so a coloured residual that does not
// depend on the model output scores about 3/N, as a white one does.
// (Ljung, System Identification, 1999, §16.6: residual analysis, and §4.2 for
// the ARX structure.)
SignatureValue arx_partial_r_squared(const ResidualView& r) {
  const Eigen::Index n = r.e.size() - 2;
  if (n < 8) return {};
  Eigen::MatrixXd X(n, 5);
  X << r.e.segment(1, n), r.e.head(n), r.y_model.tail(n), r.y_model.segment(1, n),
      r.y_model.head(n);
  const Eigen::VectorXd target = r.e.tail(n);
  const double own_past = regress(target, X.leftCols(2)).r_squared;
  const double with_output = regress(target, X).r_squared;
  if (!(own_past < 1)) return {};
  return {(with_output - own_past) / (1 - own_past), {{"chance", 3.0 / double(n)}}};
}

class Arx : public KernelEffect<Arx, 5, EffectDrive::None> {
 public:
  static EffectInfo info() {
    EffectInfo i;
    i.name = "arx";
    i.summary =
        "second-order discrete transfer function (b0 + b1 z⁻¹ + b2 z⁻²)/(1 + a1 z⁻¹ + a2 z⁻²), "
        "b0 fixed by unit static gain";
    i.citation =
        "Ljung, System Identification, 2nd ed., 1999; seed Hammerstein model (docs/models.md#hammerstein-seed-model)";
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
    i.statistic = {"partial R² of e on ŷ[k..k−2] given e[k−1..k−2]", arx_partial_r_squared,
                   "a second-order ARX correction of the model output explains {value} of the "
                   "residual variance that the residual's own past leaves (about {chance} by "
                   "chance)"};
    return i;
  }

  // c = (b0, b1, b2, a1, a2).
  static EffectSetup setup(std::span<const double> p, double, std::array<double, 5>& c) {
    const double a1 = p[0], a2 = p[1], b1 = p[2], b2 = p[3];
    for (double x : p)
      if (!std::isfinite(x)) return EffectSetup::Invalid;
    if (a1 == 0.0 && a2 == 0.0 && b1 == 0.0 && b2 == 0.0) return EffectSetup::PassThrough;
    if (!(std::abs(a2) < 1.0 && std::abs(a1) < 1.0 + a2)) return EffectSetup::Invalid;
    c = {(1.0 + a1 + a2) - (b1 + b2), b1, b2, a1, a2};
    return EffectSetup::Run;
  }

  template <class V>
  using State = BiquadState<V>;

  template <class V>
  static V sample(const std::array<V, 5>& c, NoAux, State<V>& state, V signal, double) {
    return biquad_step(c, state, signal);
  }

  // The last output sample.
  template <class V>
  static V health(const std::array<V, 5>&, const State<V>& state) {
    return state.y1;
  }
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_EFFECT(hystbench::Arx)
