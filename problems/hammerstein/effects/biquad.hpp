#pragma once
// The second-order section that the linear dynamics effects (arx, msd) run,
//   y[k] = b0·w[k] + b1·w[k−1] + b2·w[k−2] − a1·y[k−1] − a2·y[k−2],
// from rest (w[k<0] = y[k<0] = 0), one sample at a time. Batch loops and
// steppers both call it, so the two forms agree bit for bit; V is double or
// a lane vector.
#include <array>

namespace hystbench {

template <class V>
struct BiquadState {
  V w1{}, w2{}, y1{}, y2{};
};

// c = (b0, b1, b2, a1, a2).
template <class V>
inline V biquad_step(const std::array<V, 5>& c, BiquadState<V>& s, V w) {
  const V y = ((c[0] * w + c[1] * s.w1) + (c[2] * s.w2 - c[4] * s.y2)) - c[3] * s.y1;
  s.w2 = s.w1;
  s.w1 = w;
  s.y2 = s.y1;
  s.y1 = y;
  return y;
}

// A resonance 1 / (s²/ω² + 2ζs/ω + 1) under the bilinear map
// s = (2/Ts)(z − 1)/(z + 1), multiplied by (z + 1)², has the denominator
// (k² + q + 1, 2 − 2k², k² − q + 1) with k = 2/(ωTs) and q = 2ζk; msd and
// second_mode build their sections from these terms.
struct TustinResonance {
  double k2, q, a0;  // k², q and the leading coefficient k² + q + 1
};
inline TustinResonance tustin_resonance(double k, double zeta) {
  const double k2 = k * k, q = 2.0 * zeta * k;
  return {k2, q, k2 + q + 1.0};
}

}  // namespace hystbench
