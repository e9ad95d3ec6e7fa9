#include "problems/hammerstein/recurrence_coefficients.hpp"

namespace hystbench {

MsdCoefficients::MsdCoefficients(const HammersteinParams& p, double Ts)
    : e(Ts * Ts),
      f(2 * Ts * Ts),
      g(Ts * Ts),
      e1(4 * p.M + 2 * p.D * Ts + p.K * Ts * Ts),
      f1(2 * p.K * Ts * Ts - 8 * p.M),
      g1(4 * p.M - 2 * p.D * Ts + p.K * Ts * Ts) {}

RecurrenceCoefficients::RecurrenceCoefficients(const HammersteinParams& p, double Ts)
    : beta(p.beta), aL(p.alpha * p.L), gamma(p.gamma), d1(p.d1), d2(p.d2), a(p.a), b(p.b), c(p.c),
      d(p.d) {
  // Normalised once so that the recursion divides by nothing.
  const MsdCoefficients m(p, Ts);
  k_h0 = m.e / m.e1;
  k_h1 = m.f / m.e1;
  k_h2 = m.g / m.e1;
  k_r1 = -m.f1 / m.e1;
  k_r2 = -m.g1 / m.e1;
}

}  // namespace hystbench
