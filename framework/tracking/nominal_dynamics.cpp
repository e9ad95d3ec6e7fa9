#include "framework/tracking/nominal_dynamics.hpp"

#include <algorithm>
#include <cmath>
#include <nlopt.hpp>
#include <tuple>

#include "framework/core/error.hpp"
#include "framework/core/rng.hpp"
#include "framework/core/text.hpp"
#include "framework/robust/linear_system.hpp"
#include "framework/svr/arx_fit.hpp"

namespace hystbench {
namespace {

constexpr int kSamples = 20000;
constexpr int kSamplesPerStep = 10;  // the excitation's band reaches a tenth of the sampling rate

// The output error of the ARX structure with coefficients x = [a; b].
double output_error(const std::vector<double>& x, ArxFit& fit, const Eigen::VectorXd& v, const Eigen::VectorXd& y) {
  for (int i = 0; i < fit.p; ++i) fit.a[i] = x[i];
  for (int i = 0; i < fit.q; ++i) fit.b[i] = x[fit.p + i];
  const Eigen::VectorXd simulated = fit.simulate(v);
  const double sse = (simulated - y).squaredNorm();
  return std::isfinite(sse) ? sse : 1e300;
}

// Equation-error least squares is biased when the back is not exactly of
// the chosen orders (a bilinear resonance seen one sample late is not): the
// coefficients are refined on the simulated output error from there, so L
// keeps the back's static gain and resonance.
void refine_output_error(ArxFit& fit, const Eigen::VectorXd& v, const Eigen::VectorXd& y) {
  std::vector<double> x(fit.a.data(), fit.a.data() + fit.p);
  x.insert(x.end(), fit.b.data(), fit.b.data() + fit.q);
  nlopt::opt opt(nlopt::LN_SBPLX, unsigned(x.size()));
  std::vector<double> step(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) step[i] = 1e-2 * std::max(std::abs(x[i]), 1e-3);
  opt.set_initial_step(step);
  ArxFit trial = fit;
  std::tuple<ArxFit*, const Eigen::VectorXd*, const Eigen::VectorXd*> args{&trial, &v, &y};
  opt.set_min_objective(
      [](const std::vector<double>& c, std::vector<double>&, void* data) {
        auto* a = static_cast<std::tuple<ArxFit*, const Eigen::VectorXd*, const Eigen::VectorXd*>*>(data);
        return output_error(c, *std::get<0>(*a), *std::get<1>(*a), *std::get<2>(*a));
      },
      &args);
  opt.set_xtol_rel(1e-10);
  opt.set_maxeval(4000);
  double best = 0.0;
  try {
    opt.optimize(x, best);
  } catch (const std::exception&) {
    return;  // keep the least-squares coefficients
  }
  output_error(x, fit, v, y);
}

std::string roots_text(const Eigen::VectorXcd& roots) {
  std::string out;
  for (const auto& r : roots)
    out += (out.empty() ? "" : ", ") + format_number("%.5g", r.real()) +
           (r.imag() != 0.0 ? (r.imag() > 0 ? "+" : "-") + format_number("%.5g", std::abs(r.imag())) + "i" : "");
  return out;
}

double max_modulus(const Eigen::VectorXcd& roots) {
  return roots.size() ? roots.cwiseAbs().maxCoeff() : 0.0;
}

// L(z) = (b_0 z^{n−1} + … + b_{q−1} z^{n−q}) / (z^n + a_1 z^{n−1} + … + a_p z^{n−p}), n = max(p, q):
// the ARX model of y(k) on w(k − 1) .. w(k − q).
NominalDynamics nominal_from_arx(const ArxFit& fit, double sample_time, const std::string& where) {
  const int n = std::max(fit.p, fit.q);
  std::vector<double> num(n + 1, 0.0), den(n + 1, 0.0);
  den[0] = 1.0;
  for (int i = 0; i < fit.p; ++i) den[i + 1] = fit.a[i];
  for (int i = 0; i < fit.q; ++i) num[i + 1] = fit.b[i];
  NominalDynamics out = nominal_from_transfer(num, den, sample_time, where);
  out.p = fit.p, out.q = fit.q;
  return out;
}

}  // namespace

NominalDynamics nominal_from_transfer(std::vector<double> num, std::vector<double> den, double sample_time,
                                      const std::string& where) {
  NominalDynamics n;
  n.sample_time = sample_time;
  n.discrete = robust::transfer_function(num, den);
  if (n.discrete.D(0, 0) != 0.0)
    throw InputError(where + ": L(z) must be strictly proper (the loop applies an input one sample late)");
  // Wr = 1/(z L) is proper only when L is one sample late and no more.
  if (robust::polynomial_roots(num).size() + 1 != robust::poles(n.discrete).size())
    throw InputError(where + ": L(z) must have one pole more than zeros, so that 1/(z L) is proper; its "
                             "first numerator coefficient b_0 is zero");
  const Eigen::VectorXcd poles = robust::poles(n.discrete), zeros = robust::polynomial_roots(num);
  if (max_modulus(poles) >= 1.0)
    throw InputError(where + ": L(z) is unstable (poles " + roots_text(poles) +
                     "); the design needs a stable nominal model");
  if (max_modulus(zeros) >= 1.0)
    throw InputError(where + ": L(z) has a zero on or outside the unit circle (" + roots_text(zeros) +
                     "), so the feedforward 1/(z L) would be unstable; identify L with other orders");
  std::vector<double> z_num = num;
  z_num.push_back(0.0);  // z·num
  n.feedforward = robust::transfer_function(den, z_num);
  n.num = std::move(num);
  n.den = std::move(den);
  return n;
}

NominalDynamics identify_dynamics(const IdentifiedModel& model, double sample_time, int p, int q,
                                  std::uint64_t seed, const std::string& where) {
  if (p < 1 || q < 1 || p > 8 || q > 8) throw InputError(where + ": the orders p and q must be in 1..8");
  auto stream = model.clone();
  stream->reset();
  // The back is linear and works on any scale; a random staircase with a
  // few samples per step excites it up to a fraction of the Nyquist rate.
  Rng rng(seed);
  Eigen::VectorXd w(kSamples), y(kSamples);
  double level = 0.0;
  for (int k = 0; k < kSamples; ++k) {
    if (k % kSamplesPerStep == 0) level = rng.normal();
    w[k] = level;
  }
  // The loop measures at k + 1 what the back made of w[k]: fit y from w
  // delayed by one sample, so that b_0 multiplies w(k − 1).
  Eigen::VectorXd delayed = Eigen::VectorXd::Zero(kSamples);
  for (int k = 0; k < kSamples; ++k) {
    y[k] = stream->step_back(k > 0 ? w[k - 1] : 0.0);
    if (k > 0) delayed[k] = w[k - 1];
  }
  if (!y.allFinite()) throw InputError(where + ": the model's dynamics diverge; check its parameters");
  const ArxFit least_squares = fit_arx(delayed, y, p, q, std::max(p, q), where);
  ArxFit refined = least_squares;
  refine_output_error(refined, delayed, y);
  // The output error does not see where the zeros go: should the refined
  // L fail the checks the least-squares one passes, the latter is kept.
  NominalDynamics out;
  ArxFit fit = refined;
  try {
    out = nominal_from_arx(refined, sample_time, where);
  } catch (const InputError&) {
    out = nominal_from_arx(least_squares, sample_time, where);  // throws the reason when neither passes
    fit = least_squares;
  }
  const Eigen::VectorXd simulated = fit.simulate(delayed);
  const double rms = std::sqrt(y.squaredNorm() / kSamples);
  out.misfit = rms > 0 ? std::sqrt((simulated - y).squaredNorm() / kSamples) / rms : 0.0;
  return out;
}

}  // namespace hystbench
