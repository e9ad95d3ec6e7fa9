#include "framework/robust/linear_system.hpp"

#include "framework/core/eigen.hpp"
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <unsupported/Eigen/MatrixFunctions>

#include "framework/core/error.hpp"

namespace hystbench::robust {
namespace {

std::vector<double> without_leading_zeros(std::vector<double> c) {
  const auto first = std::find_if(c.begin(), c.end(), [](double v) { return v != 0.0; });
  c.erase(c.begin(), first);
  return c;
}

void require_consistent(const StateSpace& s, const char* what) {
  if (!s.consistent()) throw InputError(std::string(what) + ": the system's matrices have inconsistent sizes");
}

void require_siso(const StateSpace& s, const char* what) {
  require_consistent(s, what);
  if (s.inputs() != 1 || s.outputs() != 1)
    throw InputError(std::string(what) + ": needs a system of one input and one output");
}

}  // namespace

StateSpace transfer_function(std::vector<double> num, std::vector<double> den) {
  den = without_leading_zeros(std::move(den));
  num = without_leading_zeros(std::move(num));
  if (den.empty()) throw InputError("transfer_function: the denominator is zero");
  if (num.size() > den.size())
    throw InputError("transfer_function: the numerator's degree exceeds the denominator's (not proper)");
  const double lead = den.front();
  for (double& c : den) c /= lead;
  for (double& c : num) c /= lead;
  const Eigen::Index n = Eigen::Index(den.size()) - 1;
  num.insert(num.begin(), den.size() - num.size(), 0.0);
  StateSpace s{Eigen::MatrixXd::Zero(n, n), Eigen::MatrixXd::Zero(n, 1), Eigen::MatrixXd::Zero(1, n),
               Eigen::MatrixXd::Constant(1, 1, num[0])};
  for (Eigen::Index i = 0; i < n; ++i) {
    s.A(0, i) = -den[i + 1];
    s.C(0, i) = num[i + 1] - num[0] * den[i + 1];
    if (i + 1 < n) s.A(i + 1, i) = 1.0;
  }
  if (n > 0) s.B(0, 0) = 1.0;
  return s;
}

Eigen::VectorXcd polynomial_roots(const std::vector<double>& coefficients) {
  const std::vector<double> c = without_leading_zeros(coefficients);
  if (c.size() <= 1) return Eigen::VectorXcd(0);
  return poles(transfer_function({1.0}, c));
}

Eigen::VectorXcd poles(const StateSpace& system) {
  if (system.states() == 0) return Eigen::VectorXcd(0);
  return Eigen::EigenSolver<Eigen::MatrixXd>(system.A, false).eigenvalues();
}

Eigen::VectorXcd zeros(const StateSpace& system) {
  require_siso(system, "zeros");
  const Eigen::Index n = system.states();
  Eigen::MatrixXd pencil(n + 1, n + 1), identity = Eigen::MatrixXd::Zero(n + 1, n + 1);
  pencil << system.A, system.B, system.C, system.D;
  identity.topLeftCorner(n, n).setIdentity();
  Eigen::GeneralizedEigenSolver<Eigen::MatrixXd> qz(pencil, identity, false);
  const Eigen::VectorXcd alpha = qz.alphas();
  const Eigen::VectorXd beta = qz.betas();
  const double scale = std::max(1.0, pencil.cwiseAbs().maxCoeff());
  std::vector<std::complex<double>> finite;
  for (Eigen::Index i = 0; i < alpha.size(); ++i)
    if (std::abs(beta[i]) * scale > 1e3 * std::numeric_limits<double>::epsilon() * std::abs(alpha[i]))
      finite.push_back(alpha[i] / beta[i]);
  return Eigen::Map<Eigen::VectorXcd>(finite.data(), Eigen::Index(finite.size()));
}

double stability_margin(const StateSpace& system, TimeDomain domain) {
  double margin = -std::numeric_limits<double>::infinity();
  for (const std::complex<double>& p : poles(system))
    margin = std::max(margin, domain == TimeDomain::Continuous ? p.real() : std::abs(p));
  return margin;
}

bool is_stable(const StateSpace& system, TimeDomain domain) {
  return stability_margin(system, domain) < (domain == TimeDomain::Continuous ? 0.0 : 1.0);
}

Eigen::MatrixXcd frequency_response_matrix(const StateSpace& system, std::complex<double> x) {
  require_consistent(system, "frequency_response");
  const Eigen::Index n = system.states();
  Eigen::MatrixXcd g = system.D.cast<std::complex<double>>();
  if (n == 0) return g;
  const Eigen::MatrixXcd pencil = x * Eigen::MatrixXcd::Identity(n, n) - system.A.cast<std::complex<double>>();
  g += system.C.cast<std::complex<double>>() * pencil.partialPivLu().solve(system.B.cast<std::complex<double>>());
  return g;
}

std::complex<double> frequency_response(const StateSpace& system, std::complex<double> x) {
  require_siso(system, "frequency_response");
  return frequency_response_matrix(system, x)(0, 0);
}

std::complex<double> frequency_response_hz(const StateSpace& system, double hz, double sample_time) {
  const double w = 2.0 * std::numbers::pi * hz;
  const std::complex<double> j(0.0, 1.0);
  return frequency_response(system, sample_time > 0.0 ? std::exp(j * w * sample_time) : j * w);
}

StateSpace series(const StateSpace& first, const StateSpace& second) {
  require_consistent(first, "series");
  require_consistent(second, "series");
  if (second.inputs() != first.outputs())
    throw InputError("series: the second system must take as many inputs as the first has outputs");
  const Eigen::Index n1 = first.states(), n2 = second.states();
  StateSpace s{Eigen::MatrixXd::Zero(n1 + n2, n1 + n2), Eigen::MatrixXd(n1 + n2, first.inputs()),
               Eigen::MatrixXd(second.outputs(), n1 + n2), second.D * first.D};
  s.A.topLeftCorner(n1, n1) = first.A;
  s.A.bottomLeftCorner(n2, n1) = second.B * first.C;
  s.A.bottomRightCorner(n2, n2) = second.A;
  s.B << first.B, second.B * first.D;
  s.C << second.D * first.C, second.C;
  return s;
}

StateSpace negated(StateSpace system) {
  system.C = -system.C;
  system.D = -system.D;
  return system;
}

StateSpace parallel(const StateSpace& first, const StateSpace& second) {
  return difference(first, negated(second));
}

StateSpace lower_lft(const StateSpace& P, const StateSpace& K, int nmeas, int ncon) {
  require_consistent(P, "lower_lft");
  require_consistent(K, "lower_lft");
  const Eigen::Index n = P.states(), nk = K.states(), m1 = P.inputs() - ncon, p1 = P.outputs() - nmeas;
  if (m1 < 0 || p1 < 0 || K.inputs() != nmeas || K.outputs() != ncon)
    throw InputError("lower_lft: the controller must take the plant's " + std::to_string(nmeas) +
                     " measurements and give its " + std::to_string(ncon) + " control inputs");
  const Eigen::MatrixXd B1 = P.B.leftCols(m1), B2 = P.B.rightCols(ncon), C1 = P.C.topRows(p1),
                        C2 = P.C.bottomRows(nmeas), D11 = P.D.topLeftCorner(p1, m1),
                        D12 = P.D.topRightCorner(p1, ncon), D21 = P.D.bottomLeftCorner(nmeas, m1),
                        D22 = P.D.bottomRightCorner(nmeas, ncon);
  const Eigen::MatrixXd loop = Eigen::MatrixXd::Identity(ncon, ncon) - K.D * D22;
  Eigen::FullPivLU<Eigen::MatrixXd> lu(loop);
  if (!lu.isInvertible()) throw InputError("lower_lft: I - D22 DK is singular: the loop is not well posed");
  // u = Ux [x; xk] + Uw w and y = Yx [x; xk] + Yw w.
  Eigen::MatrixXd Ux(ncon, n + nk), Yx(nmeas, n + nk);
  Ux << K.D * C2, K.C;
  Ux = lu.solve(Ux);
  const Eigen::MatrixXd Uw = lu.solve(K.D * D21);
  Yx << C2, Eigen::MatrixXd::Zero(nmeas, nk);
  Yx += D22 * Ux;
  const Eigen::MatrixXd Yw = D21 + D22 * Uw;
  StateSpace cl{Eigen::MatrixXd::Zero(n + nk, n + nk), Eigen::MatrixXd::Zero(n + nk, m1),
                Eigen::MatrixXd::Zero(p1, n + nk), D11 + D12 * Uw};
  cl.A.topLeftCorner(n, n) = P.A;
  cl.A.bottomRightCorner(nk, nk) = K.A;
  cl.A.topRows(n) += B2 * Ux;
  cl.A.bottomRows(nk) += K.B * Yx;
  cl.B.topRows(n) = B1 + B2 * Uw;
  cl.B.bottomRows(nk) = K.B * Yw;
  cl.C.leftCols(n) = C1;
  cl.C += D12 * Ux;
  return cl;
}

StateSpace error_feedback_plant(const StateSpace& G) {
  require_siso(G, "error_feedback_plant");
  StateSpace p{G.A, Eigen::MatrixXd(G.states(), 2), Eigen::MatrixXd(2, G.states()), Eigen::MatrixXd(2, 2)};
  p.B << Eigen::VectorXd::Zero(G.states()), G.B;
  p.C << -G.C, -G.C;
  p.D << 1.0, -G.D(0, 0), 1.0, -G.D(0, 0);
  return p;
}

double feedback_stability_margin(const StateSpace& G, const StateSpace& K, TimeDomain domain) {
  return stability_margin(lower_lft(error_feedback_plant(G), K, 1, 1), domain);
}

StateSpace zero_order_hold(const StateSpace& c, double sample_time) {
  require_consistent(c, "zero_order_hold");
  if (!(sample_time > 0.0)) throw InputError("zero_order_hold: the sampling time must be positive");
  const Eigen::Index n = c.states(), m = c.inputs();
  Eigen::MatrixXd augmented = Eigen::MatrixXd::Zero(n + m, n + m);
  augmented.topLeftCorner(n, n) = c.A * sample_time;
  augmented.topRightCorner(n, m) = c.B * sample_time;
  const Eigen::MatrixXd e = augmented.exp();
  return {e.topLeftCorner(n, n), e.topRightCorner(n, m), c.C, c.D};
}

}  // namespace hystbench::robust
