#include "framework/tracking/seed_numbers.hpp"

#include <limits>
#include <numbers>

#include "framework/core/error.hpp"
#include "framework/robust/hinf_norm.hpp"
#include "framework/robust/hinf_synthesis.hpp"
#include "framework/robust/linear_system.hpp"
#include "framework/robust/tustin.hpp"
#include "framework/tracking/hinf_design.hpp"
#include "framework/tracking/uncertainty_weight.hpp"

namespace hystbench {
namespace {

using robust::StateSpace;
using robust::TimeDomain;

constexpr double kTs = 1e-4;

// States [x_a; x_l; x_r], inputs [w1; r; u], outputs [z1; z2; y]:
// z1 = Wr r + u, z2 = y = −Wa w1 − L u (eq. 25 as printed).
StateSpace eq25_plant(const StateSpace& L, const StateSpace& wa, const StateSpace& wr) {
  const Eigen::Index na = wa.states(), nl = L.states(), nr = wr.states(), n = na + nl + nr;
  StateSpace p{Eigen::MatrixXd::Zero(n, n), Eigen::MatrixXd::Zero(n, 3), Eigen::MatrixXd::Zero(3, n),
               Eigen::MatrixXd::Zero(3, 3)};
  p.A.block(0, 0, na, na) = wa.A;
  p.A.block(na, na, nl, nl) = L.A;
  p.A.block(na + nl, na + nl, nr, nr) = wr.A;
  p.B.block(0, 0, na, 1) = wa.B;
  p.B.block(na, 2, nl, 1) = L.B;
  p.B.block(na + nl, 1, nr, 1) = wr.B;
  p.C.block(0, na + nl, 1, nr) = wr.C;
  p.D(0, 1) = wr.D(0, 0);
  p.D(0, 2) = 1.0;
  for (int row : {1, 2}) {
    p.C.block(row, 0, 1, na) = -wa.C;
    p.C.block(row, na, 1, nl) = -L.C;
    p.D(row, 0) = -wa.D(0, 0);
    p.D(row, 2) = -L.D(0, 0);
  }
  return p;
}

void check_printed(SeedNumbersCheck& c) {
  const std::vector<double> num{0.2146, -0.7352}, den{1.0, -1.4215, 1.0257};
  const StateSpace l = robust::transfer_function(num, den);
  c.l_poles = robust::poles(l);
  c.l_zeros = robust::polynomial_roots(num);
  c.l_dc_gain = (num[0] + num[1]) / (den[0] + den[1] + den[2]);
  const double k = 248.3778, z1 = 1.329e4, z2 = 2.227, p1 = 3305, p2 = 174;
  const StateSpace k3 = robust::transfer_function({k, k * (z1 + z2), k * z1 * z2}, {1.0, p1 + p2, p1 * p2, 0.0});
  const StateSpace lc = robust::inverse_tustin(l, kTs);
  c.k3_max_real = robust::feedback_stability_margin(lc, k3, TimeDomain::Continuous);
  c.k3_max_real_other_sign = robust::feedback_stability_margin(robust::negated(lc), k3, TimeDomain::Continuous);
  c.k3_spectral_radius = robust::feedback_stability_margin(l, robust::tustin(k3, kTs), TimeDomain::Discrete);
  // Wr(z) = 1/(z L(z)) = den / (z num).
  const StateSpace wr = robust::inverse_tustin(robust::transfer_function(den, {num[0], num[1], 0.0}), kTs);
  try {
    robust::hinf_synthesis(eq25_plant(lc, seed_uncertainty_weight().weight, wr), 1, 1);
    c.eq25_printed = "a controller was found";
  } catch (const InputError& e) {
    c.eq25_printed = e.what();
  }
}

// On the reference resonance of hinf_design.hpp.
void check_degenerate(SeedNumbersCheck& c) {
  const double wn = 2.0 * std::numbers::pi * 1260.0, zeta = 0.6, wr_corner = 2.0 * std::numbers::pi * 3000.0;
  const StateSpace l = reference_dynamics();
  // Wr = L⁻¹ / (s/ωr + 1)²: proper and stable.
  const double t = 1.0 / wr_corner;
  const StateSpace wr = robust::transfer_function({1.0 / (wn * wn), 2.0 * zeta / wn, 1.0}, {t * t, 2.0 * t, 1.0});
  const StateSpace p = eq25_plant(l, seed_uncertainty_weight().weight, wr);
  try {
    c.eq25_gamma_min = robust::hinf_synthesis(p, 1, 1).gamma_min;
  } catch (const InputError&) {
    c.eq25_gamma_min = std::numeric_limits<double>::quiet_NaN();  // reported as null; the check is informative only
  }
  const StateSpace open{p.A, p.B.leftCols(2), p.C.topRows(2), p.D.topLeftCorner(2, 2)};
  c.eq25_norm_without_controller = robust::hinf_norm(open, TimeDomain::Continuous).norm;
}

}  // namespace

SeedNumbersCheck check_seed_numbers() {
  SeedNumbersCheck c;
  c.sample_time = kTs;
  check_printed(c);
  check_degenerate(c);
  return c;
}

}  // namespace hystbench
