#include "problems/hammerstein/hammerstein_model.hpp"

#include "framework/core/error.hpp"
#include "problems/hammerstein/recurrence_coefficients.hpp"

#include <cmath>
#include <limits>

namespace hystbench {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Roots of z^2 + p z + q inside the unit circle.
bool stable_second_order(double p, double q) { return std::abs(q) < 1.0 && std::abs(p) < 1.0 + q; }

// One pass over the record. `Sink` receives (k, y_hat[k]) and returns false
// to abandon the simulation.
template <class Sink>
void run_model(const HammersteinParams& p, const Eigen::VectorXd& u, double Ts, BoucWenForm form,
               Sink&& sink) {
  // The recurrences are latency-bound: in each sum the previous sample's
  // state is added last, so that only one multiply and one add separate
  // consecutive samples. The batched kernel repeats these expressions
  // operation for operation (batched_sse.cpp); change both together.
  const RecurrenceCoefficients q(p, Ts);
  const bool increment = form == BoucWenForm::Increment;
  double h = 0, u_prev = 0, h1_1 = 0, h1_2 = 0, r_1 = 0, r_2 = 0, r1_1 = 0, r1_2 = 0;
  for (Eigen::Index k = 0; k < u.size(); ++k) {
    const double drive = increment ? u[k] - u_prev : u[k];
    // h + aL du - beta |du| h - gamma du |h|, grouped by h
    h = (h * (1.0 - q.beta * std::abs(drive)) + q.aL * drive) - q.gamma * drive * std::abs(h);
    const double h1 = q.d1 * u[k] + q.d2 * u[k] * u[k] - h;
    const double r = (q.k_h0 * h1 + q.k_h1 * h1_1 + q.k_h2 * h1_2 + q.k_r2 * r_2) + q.k_r1 * r_1;
    const double r1 = (q.a * r_1 + q.b * r_2 - q.d * r1_2) - q.c * r1_1;
    if (!sink(k, r1)) return;
    u_prev = u[k];
    h1_2 = h1_1;
    h1_1 = h1;
    r_2 = r_1;
    r_1 = r;
    r1_2 = r1_1;
    r1_1 = r1;
  }
}

}  // namespace

std::string to_string(BoucWenForm form) {
  return form == BoucWenForm::Increment ? "increment" : "paper";
}

BoucWenForm bouc_wen_form_from_string(const std::string& text) {
  if (text == "increment") return BoucWenForm::Increment;
  if (text == "paper") return BoucWenForm::Paper;
  throw InputError("bouc_wen_form = \"" + text + "\": use \"increment\" or \"paper\"");
}

const std::array<std::string, HammersteinParams::kCount>& HammersteinParams::names() {
  static const std::array<std::string, kCount> n{"alpha", "beta", "gamma", "L", "d1", "d2", "M",
                                                 "D",     "K",    "a",     "b", "c",  "d"};
  return n;
}

HammersteinParams HammersteinParams::from_vector(const Eigen::Ref<const Eigen::VectorXd>& x) {
  return {x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7], x[8], x[9], x[10], x[11], x[12]};
}

Eigen::VectorXd HammersteinParams::to_vector() const {
  Eigen::VectorXd x(kCount);
  x << alpha, beta, gamma, L, d1, d2, M, D, K, a, b, c, d;
  return x;
}

bool linear_blocks_stable(const HammersteinParams& p, double Ts) {
  const MsdCoefficients m(p, Ts);
  if (!(std::abs(m.e1) > 0)) return false;
  return stable_second_order(m.f1 / m.e1, m.g1 / m.e1) && stable_second_order(p.c, p.d);
}

Eigen::VectorXd simulate_hammerstein(const HammersteinParams& p, const Eigen::VectorXd& u,
                                     double Ts, BoucWenForm form) {
  Eigen::VectorXd y(u.size());
  run_model(p, u, Ts, form, [&](Eigen::Index k, double v) {
    y[k] = v;
    return true;
  });
  return y;
}

double hammerstein_sse(const HammersteinParams& p, const Eigen::VectorXd& u,
                       const Eigen::VectorXd& y, double Ts, BoucWenForm form) {
  if (!linear_blocks_stable(p, Ts)) return kInf;
  double sse = 0.0;
  run_model(p, u, Ts, form, [&](Eigen::Index k, double v) {
    const double e = y[k] - v;
    sse += e * e;
    // A diverging Bouc-Wen state ends the run early; checking every sample
    // would cost more than the rare divergence saves.
    return (k & 255) != 255 || std::isfinite(sse);
  });
  return std::isfinite(sse) ? sse : kInf;
}

}  // namespace hystbench
