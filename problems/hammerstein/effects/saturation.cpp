// Saturation of the static part (nonlinearity stage), of any shape from a
// soft bend to a hard clip:
//
//   signal[k] = L·g(signal[k] / L),   g(x) = x / (1 + |x|^p)^(1/p),
//   lambda = 1/L²,   softness = 1/p
//
// It limits the nonlinearity stage's signal as it stands when the effect
// runs: gain·v plus the nonlinearity effects listed before it (list it last
// in that stage to saturate the whole static part).
//
// Why this family: every g has slope 1 at 0 and tends to ±1, and one number
// moves the knee between them. Softness 1 is the softest (x/(1+|x|), a limit
// approached like arctan's), 0.5 the algebraic sigmoid x/√(1+x²), about 0.4
// tanh, and 0 exactly a hard clip (p = ∞), a physical shape in its own right
// rather than the edge of a search range. Fitted to arctan, tanh and a clip
// over drives up to 2.5·L, the family leaves 0.5 %, 0.5 % and 0.1 % of the
// signal; L·tanh(s/L) alone left 3.8 % of arctan and 8 % of a clip.
//
// Parameterised by the inverse squared limit lambda = 1/L² ≥ 0 so that
// lambda = 0 (L → ∞) is an exact pass-through inside the box, whatever the
// softness. At the neutral softness 0.5 the output moves linearly away from
// lambda = 0: L·g(s/L) = s − lambda·s³/2 + O(lambda²), so a local search or a
// score test started at the neutral model sees the effect; the knee sharpens
// from there. Units: lambda in 1/y², softness a plain number.

// Eigen's AVX-512 exp and log inline intrinsics that GCC 12 flags with
// -Wuninitialized (the same GCC bug 105593 that framework/core/eigen.hpp
// describes for -Wmaybe-uninitialized); only this file calls them.
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ < 13
#pragma GCC diagnostic ignored "-Wuninitialized"
#endif
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "framework/model/kernel_effect.hpp"
#include "framework/model/regressors.hpp"

namespace hystbench {
namespace {

// Signature statistic: (share of the SSE in the top |u − mean u| bin) /
// (share of the samples in it). A missing limit bends the response only at the
// largest drive, so the error crowds into the top amplitude bin; a residual
// independent of the amplitude gives 1. (Hassani et al. 2014, saturation of
// piezo actuators; bins as in the breakdown tables of `compare`.)
SignatureValue top_bin_error_share(const ResidualView& r) {
  std::vector<double> edges;
  const auto bin = amplitude_bins(r.u, edges);
  double top_sse = 0;
  long top_n = 0;
  for (std::size_t k = 0; k < bin.size(); ++k)
    if (bin[k] == kAmplitudeBins - 1) top_sse += std::pow(r.e[Eigen::Index(k)], 2), ++top_n;
  const double total = r.e.squaredNorm();
  if (bin.empty() || !(edges.back() > 0) || !(total > 0)) return {};
  const double sse_share = top_sse / total, sample_share = double(top_n) / double(bin.size());
  return {sse_share / sample_share, {{"sse_share", sse_share}, {"sample_share", sample_share}}};
}

// f (an Eigen array function) on every lane at once, by Eigen's packet code.
template <class F>
LaneVector on_lanes(LaneVector v, F f) {
  using Array = Eigen::Array<double, kEffectLanes, 1>;
  Array lanes;
  std::memcpy(lanes.data(), &v, sizeof v);
  lanes = f(lanes);
  std::memcpy(&v, lanes.data(), sizeof v);
  return v;
}

LaneVector lane_copysign(LaneVector magnitude, LaneVector sign) {
  constexpr std::int64_t kSign = std::numeric_limits<std::int64_t>::min();
  return std::bit_cast<LaneVector>((std::bit_cast<LaneBits>(magnitude) & ~kSign) |
                                   (std::bit_cast<LaneBits>(sign) & kSign));
}

// g(x) on every lane: b = min(|x|, 1/|x|), whose power never overflows
// (beyond the knee g(x) = sign(x)·(1 + |x|^-p)^(-1/p)), then
//   t = exp(p·ln b),  r = exp(−softness·ln(1 + t)),
// by Eigen's vectorised log, exp and log1p on the whole lane vector. A chain
// with saturation then costs what it cost with one std::tanh per lane, and
// less than half of two std::pow per lane (BM_WiderModelProblemBatched: 26
// against 69 ns per sample and candidate). Softness 0 (p = ∞) sets t to 0
// inside the knee and to b = 1 on it, as pow would, and keeps a NaN a NaN.
LaneVector unit_limit(LaneVector x, LaneVector p, LaneVector softness) {
  const LaneVector a = lane_abs(x);
  const LaneBits inside = a <= 1.0;
  const LaneVector b = inside ? a : 1.0 / a;
  const LaneVector log_b = on_lanes(b, [](const auto& v) { return v.log(); });
  LaneVector t = on_lanes(p * log_b, [](const auto& v) { return v.exp(); });
  t = softness == 0.0 ? (b < 1.0 ? LaneVector{} : b) : t;
  const LaneVector log_1t = on_lanes(t, [](const auto& v) { return v.log1p(); });
  const LaneVector r = on_lanes(-softness * log_1t, [](const auto& v) { return v.exp(); });
  return lane_copysign(inside ? a * r : r, x);
}

// One candidate takes lane 0 of the same code, so both forms agree bit for bit.
double unit_limit(double x, double p, double softness) {
  return unit_limit(LaneVector{} + x, LaneVector{} + p, LaneVector{} + softness)[0];
}

class Saturation : public KernelEffect<Saturation, 4, EffectDrive::None> {
 public:
  static EffectInfo info() {
    EffectInfo i;
    i.name = "saturation";
    i.summary = "limit L·g(s/L) on the static part's output, g(x) = x/(1+|x|^p)^(1/p), from a soft "
                "bend (softness 1/p = 1) to a hard clip (0); parameterised by 1/L²";
    i.citation =
        "Hassani, Tjahjowidodo & Do, Mech. Syst. Signal Process. 49 (2014) (survey); "
        "MATLAB nlhw saturation block";
    i.stage = EffectStage::Nonlinearity;
    i.params = {{"lambda", 0.0, 4.0, 0.0, -2, 0, "",
                 "inverse squared output limit 1/L² (0 = no saturation)"},
                {"softness", 0.0, 1.0, 0.5, 0, 0, "",
                 "shape of the knee, 1/p: 0 a hard clip, about 0.4 tanh, 0.5 x/√(1+x²), 1 x/(1+|x|)",
                 true}};
    i.signature =
        "the error is concentrated in the top amplitude bin and the residual carries a third "
        "harmonic of the drive";
    i.statistic = {"top-bin SSE share / sample share", top_bin_error_share,
                   "the top amplitude bin holds {value} times its share of the samples in "
                   "squared error ({sse_share} of the SSE on {sample_share} of the samples)"};
    // At one amplitude a flattened top and an even-order bend are both one
    // fixed distortion of the loop; only a second amplitude shows which
    // grows how.
    i.rivals = {{"asymmetry", ExcitationNeed::SeveralAmplitudes}};
    return i;
  }

  // c = (1/L, L, p, softness); softness 0 gives p = ∞, the clip.
  static EffectSetup setup(std::span<const double> p, double /*Ts*/, std::array<double, 4>& c) {
    const double lambda = p[0], softness = p[1];
    if (!std::isfinite(lambda) || lambda < 0.0 || !(softness >= 0.0 && softness <= 1.0))
      return EffectSetup::Invalid;
    if (lambda == 0.0) return EffectSetup::PassThrough;
    const double inverse_limit = std::sqrt(lambda);
    c = {inverse_limit, 1.0 / inverse_limit,
         softness > 0.0 ? 1.0 / softness : std::numeric_limits<double>::infinity(), softness};
    return std::isfinite(c[1]) ? EffectSetup::Run : EffectSetup::Invalid;
  }

  template <class V>
  static V sample(const std::array<V, 4>& c, NoAux, State<V>&, V signal, double) {
    return c[1] * unit_limit(c[0] * signal, c[2], c[3]);
  }

  // Stateless: nothing can diverge.
  template <class V>
  static V health(const std::array<V, 4>&, const State<V>&) {
    return V{};
  }
};

}  // namespace
}  // namespace hystbench

HYSTBENCH_EFFECT(hystbench::Saturation)
