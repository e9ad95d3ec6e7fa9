#include "problems/hammerstein/hammerstein_model.hpp"

#include "framework/core/error.hpp"
#include "problems/hammerstein/recurrence_coefficients.hpp"
#include "problems/hammerstein/seed_step.hpp"

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
  const RecurrenceCoefficients q(p, Ts);
  const bool increment = form == BoucWenForm::Increment;
  SeedState<double> state;
  double u_prev = 0;
  for (Eigen::Index k = 0; k < u.size(); ++k) {
    const double drive = increment ? u[k] - u_prev : u[k];
    if (!sink(k, seed_step(state, q, drive, std::abs(drive), u[k]))) return;
    u_prev = u[k];
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
