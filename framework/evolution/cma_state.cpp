#include "framework/evolution/cma_state.hpp"

#include "framework/core/eigen.hpp"
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "framework/evolution/population.hpp"

namespace hystbench {
namespace {

// Stopping thresholds of the tutorial (docs/algorithms.md#stopping-and-ipop-restarts).
constexpr double tol_fun = 1e-12;
constexpr double tol_x_factor = 1e-12;  // times sigma_0
constexpr double max_condition = 1e14;

int history_length(const CmaSettings& s) {
  return 10 + static_cast<int>(std::ceil(30.0 * s.n / s.lambda));
}

}  // namespace

int cma_default_lambda(int n) { return 4 + static_cast<int>(std::floor(3.0 * std::log(n))); }

CmaSettings cma_settings(int n, int lambda) {
  if (n < 1 || lambda < 2) throw std::invalid_argument("CMA-ES needs n >= 1 and lambda >= 2");
  CmaSettings s;
  s.n = n;
  s.lambda = lambda;
  s.mu = lambda / 2;
  s.weights.resize(s.mu);
  for (int i = 0; i < s.mu; ++i) s.weights[i] = std::log((lambda + 1) / 2.0) - std::log(i + 1.0);
  s.weights /= s.weights.sum();
  s.mu_eff = 1.0 / s.weights.squaredNorm();  // (sum w)^2 / sum w^2 with sum w = 1
  const double dn = n;
  s.c_sigma = (s.mu_eff + 2) / (dn + s.mu_eff + 5);
  s.d_sigma = 1 + 2 * std::max(0.0, std::sqrt((s.mu_eff - 1) / (dn + 1)) - 1) + s.c_sigma;
  s.c_c = (4 + s.mu_eff / dn) / (dn + 4 + 2 * s.mu_eff / dn);
  s.c_1 = 2 / ((dn + 1.3) * (dn + 1.3) + s.mu_eff);
  s.c_mu = std::min(1 - s.c_1,
                    2 * (s.mu_eff - 2 + 1 / s.mu_eff) / ((dn + 2) * (dn + 2) + s.mu_eff));
  s.chi_n = std::sqrt(dn) * (1 - 1 / (4 * dn) + 1 / (21 * dn * dn));
  s.eigen_interval = std::max(1, static_cast<int>(std::floor(1 / (10 * dn * (s.c_1 + s.c_mu)))));
  return s;
}

CmaState::CmaState(CmaSettings settings, Eigen::VectorXd mean, double sigma)
    : s_(std::move(settings)),
      mean_(std::move(mean)),
      sigma_(sigma),
      sigma0_(sigma),
      C_(Eigen::MatrixXd::Identity(s_.n, s_.n)),
      BD_(C_),
      inv_sqrt_C_(C_),
      eigenvalues_(Eigen::VectorXd::Ones(s_.n)),
      p_sigma_(Eigen::VectorXd::Zero(s_.n)),
      p_c_(Eigen::VectorXd::Zero(s_.n)) {}

Eigen::MatrixXd CmaState::sample_steps(Rng& rng) const {
  Eigen::MatrixXd Z(s_.n, s_.lambda);
  for (int k = 0; k < s_.lambda; ++k)
    for (int j = 0; j < s_.n; ++j) Z(j, k) = rng.normal();
  return BD_ * Z;
}

void CmaState::update(const Eigen::MatrixXd& steps, const Eigen::VectorXd& f) {
  const auto order = rank_order(f);
  Eigen::MatrixXd best(s_.n, s_.mu);
  for (int i = 0; i < s_.mu; ++i) best.col(i) = steps.col(order[i]);
  const Eigen::VectorXd y_w = best * s_.weights;
  mean_ += sigma_ * y_w;  // c_m = 1
  update_paths_and_sigma(y_w);
  update_covariance(best);
  record_fitness(f[order.front()], f[order.back()]);
  ++generation_;
  if (++since_decomposition_ >= s_.eigen_interval) decompose();
}

void CmaState::update_paths_and_sigma(const Eigen::VectorXd& y_w) {
  const double cs = s_.c_sigma;
  p_sigma_ = (1 - cs) * p_sigma_ + std::sqrt(cs * (2 - cs) * s_.mu_eff) * (inv_sqrt_C_ * y_w);
  const double ps_norm = p_sigma_.norm();
  sigma_ *= std::exp((cs / s_.d_sigma) * (ps_norm / s_.chi_n - 1));
  // The bias correction makes h_sigma independent of how young the path is.
  const double correction = std::sqrt(1 - std::pow(1 - cs, 2.0 * (generation_ + 1)));
  h_sigma_ = ps_norm / correction < (1.4 + 2.0 / (s_.n + 1)) * s_.chi_n;
  const double cc = s_.c_c;
  p_c_ = (1 - cc) * p_c_;
  if (h_sigma_) p_c_ += std::sqrt(cc * (2 - cc) * s_.mu_eff) * y_w;
}

void CmaState::update_covariance(const Eigen::MatrixXd& best_steps) {
  const double delta = h_sigma_ ? 0.0 : s_.c_c * (2 - s_.c_c);
  C_ *= 1 + s_.c_1 * delta - s_.c_1 - s_.c_mu;
  C_ += s_.c_1 * (p_c_ * p_c_.transpose());
  C_ += s_.c_mu * (best_steps * s_.weights.asDiagonal() * best_steps.transpose());
}

void CmaState::record_fitness(double best, double worst) {
  best_history_.push_back(best);
  while (static_cast<int>(best_history_.size()) > history_length(s_)) best_history_.pop_front();
  last_best_ = best;
  last_worst_ = worst;
}

void CmaState::decompose() {
  C_ = 0.5 * (C_ + C_.transpose()).eval();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(C_);
  eigenvalues_ = eig.eigenvalues();
  const Eigen::VectorXd d = eigenvalues_.cwiseMax(0.0).cwiseSqrt();
  const Eigen::MatrixXd& B = eig.eigenvectors();
  BD_ = B * d.asDiagonal();
  inv_sqrt_C_ = B * d.cwiseInverse().asDiagonal() * B.transpose();
  since_decomposition_ = 0;
}

CmaStop CmaState::stop() const {
  if (fitness_range_below_tolerance()) return CmaStop::TolFun;
  // Negated comparisons, so that a NaN from a numerical breakdown stops too.
  const double largest_sd = sigma_ * std::sqrt(C_.diagonal().maxCoeff());
  if (!(largest_sd >= tol_x_factor * sigma0_)) return CmaStop::TolX;
  if (!(eigenvalues_.maxCoeff() <= max_condition * eigenvalues_.minCoeff()))
    return CmaStop::ConditionCov;
  if (no_effect_axis()) return CmaStop::NoEffectAxis;
  if (no_effect_coordinate()) return CmaStop::NoEffectCoord;
  return CmaStop::None;
}

// Range of the generation-best values over the last 10 + ceil(30 n / lambda)
// generations together with all values of the last generation. An infinite
// value makes the range inf or NaN, so a diverged run never counts as flat.
bool CmaState::fitness_range_below_tolerance() const {
  if (static_cast<int>(best_history_.size()) < history_length(s_)) return false;
  const auto [lo, hi] = std::minmax_element(best_history_.begin(), best_history_.end());
  const double range = std::max(*hi, last_worst_) - std::min(*lo, last_best_);
  return range < tol_fun;
}

// One principal axis per generation, cycling, as in the IPOP-CMA-ES code.
bool CmaState::no_effect_axis() const {
  const int i = generation_ % s_.n;
  return (mean_ + 0.1 * sigma_ * BD_.col(i)).cwiseEqual(mean_).all();
}

bool CmaState::no_effect_coordinate() const {
  const Eigen::VectorXd sd = C_.diagonal().cwiseSqrt();
  return (mean_ + 0.2 * sigma_ * sd).cwiseEqual(mean_).any();
}

}  // namespace hystbench
