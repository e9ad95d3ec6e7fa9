#pragma once
// What a designer asks of a linear system besides synthesis: building one
// from a transfer function, its poles and zeros, its frequency response,
// series and feedback connections and sampling by zero-order hold. Plain
// Eigen: SLICOT is not needed for any of these.
#include "framework/core/eigen.hpp"
#include <complex>
#include <vector>

#include "framework/robust/hinf_norm.hpp"
#include "framework/robust/state_space.hpp"

namespace hystbench::robust {

// num(x)/den(x) with coefficients of the highest power first, in s or z:
// the controllable canonical realisation. Leading zeros are dropped.
// Throws InputError when den is zero or the fraction is not proper.
StateSpace transfer_function(std::vector<double> num, std::vector<double> den);

// Roots of a polynomial, highest power first (leading zeros ignored).
Eigen::VectorXcd polynomial_roots(const std::vector<double>& coefficients);

Eigen::VectorXcd poles(const StateSpace& system);
// Transmission zeros of a single-input single-output system (the finite
// eigenvalues of its Rosenbrock pencil).
Eigen::VectorXcd zeros(const StateSpace& system);

// Stable: every pole in the open left half plane, or inside the unit circle.
bool is_stable(const StateSpace& system, TimeDomain domain);
// max Re p (continuous) or max |p| (discrete); -inf without states.
double stability_margin(const StateSpace& system, TimeDomain domain);

// C (xI − A)⁻¹ B + D at x = s or z.
Eigen::MatrixXcd frequency_response_matrix(const StateSpace& system, std::complex<double> x);
// The same for a single-input single-output system.
std::complex<double> frequency_response(const StateSpace& system, std::complex<double> x);
// The same at f hertz: s = j2πf, or z = exp(j2πf·Ts) when sample_time > 0.
std::complex<double> frequency_response_hz(const StateSpace& system, double hz, double sample_time = 0.0);

// second(first(u)).
StateSpace series(const StateSpace& first, const StateSpace& second);
// −system.
StateSpace negated(StateSpace system);
// first + second, on the same input.
StateSpace parallel(const StateSpace& first, const StateSpace& second);
// The lower linear fractional transformation: P's last `nmeas` outputs feed
// K, whose outputs are P's last `ncon` inputs (u = K y, SLICOT's sign).
// Throws InputError when the loop is not well posed (I − D22 DK singular).
StateSpace lower_lft(const StateSpace& P, const StateSpace& K, int nmeas, int ncon);

// [r; u] -> [e; e] with e = r − G u, for a single-input single-output G:
// closed by lower_lft with u = K e it is the unity-feedback loop (its
// output the sensitivity S r), its state matrix the loop's.
StateSpace error_feedback_plant(const StateSpace& G);
// stability_margin() of that loop closed with u = K e.
double feedback_stability_margin(const StateSpace& G, const StateSpace& K, TimeDomain domain);

// Exact sampling with the input held constant over each interval.
StateSpace zero_order_hold(const StateSpace& continuous, double sample_time);

}  // namespace hystbench::robust
