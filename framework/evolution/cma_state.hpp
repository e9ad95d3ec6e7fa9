#pragma once
// The (mu/mu_w, lambda)-CMA-ES of Hansen's tutorial, positive weights only
// (docs/algorithms.md#cma-es): the default strategy parameters, one generation's
// sampling and update, and the stopping tests that end a run or trigger an
// IPOP restart. The state knows nothing of bounds or budgets; the caller
// maps the sampled points into the box and evaluates them.
#include "framework/core/eigen.hpp"
#include <deque>

#include "framework/core/rng.hpp"

namespace hystbench {

// The tutorial's defaults table for dimension n and population lambda.
struct CmaSettings {
  int n = 0;
  int lambda = 0;
  int mu = 0;
  Eigen::VectorXd weights;  // mu positive recombination weights, summing to 1
  double mu_eff = 0.0;
  double c_sigma = 0.0;
  double d_sigma = 0.0;
  double c_c = 0.0;
  double c_1 = 0.0;
  double c_mu = 0.0;
  double chi_n = 0.0;      // E||N(0, I)||
  int eigen_interval = 1;  // generations between eigendecompositions of C
};

// 4 + floor(3 ln n).
int cma_default_lambda(int n);
CmaSettings cma_settings(int n, int lambda);

enum class CmaStop { None, TolFun, TolX, ConditionCov, NoEffectAxis, NoEffectCoord };

class CmaState {
 public:
  // C = I, evolution paths zero; `sigma` is also the sigma_0 of TolX.
  CmaState(CmaSettings settings, Eigen::VectorXd mean, double sigma);

  // lambda steps y_k = B D z_k with z_k ~ N(0, I), one per column; the
  // candidates are mean() + sigma() y_k.
  Eigen::MatrixXd sample_steps(Rng& rng) const;
  // One generation's update from the sampled steps and their fitness.
  void update(const Eigen::MatrixXd& steps, const Eigen::VectorXd& f);
  // The first stopping criterion that holds after the last update.
  CmaStop stop() const;

  const CmaSettings& settings() const { return s_; }
  const Eigen::VectorXd& mean() const { return mean_; }
  double sigma() const { return sigma_; }
  const Eigen::MatrixXd& covariance() const { return C_; }
  int generation() const { return generation_; }

 private:
  void update_paths_and_sigma(const Eigen::VectorXd& y_w);
  void update_covariance(const Eigen::MatrixXd& best_steps);
  void record_fitness(double best, double worst);
  void decompose();
  bool fitness_range_below_tolerance() const;
  bool no_effect_axis() const;
  bool no_effect_coordinate() const;

  CmaSettings s_;
  Eigen::VectorXd mean_;
  double sigma_;
  double sigma0_;
  Eigen::MatrixXd C_;
  Eigen::MatrixXd BD_;          // B D of the last decomposition: samples y = B D z
  Eigen::MatrixXd inv_sqrt_C_;  // B D^-1 B^T of the last decomposition
  Eigen::VectorXd eigenvalues_;
  Eigen::VectorXd p_sigma_;
  Eigen::VectorXd p_c_;
  bool h_sigma_ = true;
  int generation_ = 0;
  int since_decomposition_ = 0;
  std::deque<double> best_history_;  // generation-best fitness, newest last
  double last_best_ = 0.0;
  double last_worst_ = 0.0;
};

}  // namespace hystbench
