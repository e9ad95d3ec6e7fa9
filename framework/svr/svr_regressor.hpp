#pragma once
// An epsilon-SVR with an RBF kernel, trained by libsvm
// (docs/svr.md#stage-1): K(u, v) = exp(-|u - v|^2 / (2 sigma^2)), i.e.
// libsvm's gamma = 1 / (2 sigma^2). After training, the support vectors,
// their coefficients and rho are copied out of libsvm and kept here, so a
// trained model and one loaded from JSON predict through the same code
// (libsvm's svm_predict) with the same numbers, bit for bit.
#include "framework/core/eigen.hpp"
#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

namespace hystbench {

struct SvrHyperparameters {
  double epsilon = 0.01;  // half-width of the insensitive tube (libsvm's p)
  double C = 1.0;         // box constraint
  double sigma = 1.0;     // RBF width
  double gamma() const { return 1.0 / (2.0 * sigma * sigma); }
  // From (log10 epsilon, log10 C, log10 sigma): the svr_hyperparameters
  // problem's decision variables.
  static SvrHyperparameters from_log10(double epsilon, double C, double sigma) {
    return {std::pow(10.0, epsilon), std::pow(10.0, C), std::pow(10.0, sigma)};
  }
};

class SvrRegressor {
 public:
  // Trains on the rows of `inputs` (one sample per row) and `targets`.
  // Throws InputError naming `where` with libsvm's own message when a
  // hyperparameter is invalid, and when the data are empty or mismatched.
  // The checks train() makes of `h` alone (ours, then libsvm's
  // svm_check_parameter), for validating an experiment before any work.
  static void check(const SvrHyperparameters& h, const std::string& where);
  static SvrRegressor train(const Eigen::MatrixXd& inputs, const Eigen::VectorXd& targets,
                            const SvrHyperparameters& h, const std::string& where);

  SvrRegressor(const SvrRegressor& other);
  SvrRegressor& operator=(const SvrRegressor& other);
  SvrRegressor(SvrRegressor&&) noexcept;
  SvrRegressor& operator=(SvrRegressor&&) noexcept;
  ~SvrRegressor();

  // libsvm's own cross-validation (random folds): the out-of-fold
  // prediction of every row. libsvm draws the folds from the C library's
  // global rand(), so calls are serialised and rand() is seeded with `seed`
  // first: the same seed gives the same folds on any thread.
  static Eigen::VectorXd libsvm_cross_validation(const Eigen::MatrixXd& inputs,
                                                 const Eigen::VectorXd& targets,
                                                 const SvrHyperparameters& h, int folds,
                                                 unsigned seed, const std::string& where);

  double predict(const Eigen::Ref<const Eigen::VectorXd>& input) const;
  int dimension() const;
  int support_vectors() const;
  const SvrHyperparameters& hyperparameters() const;

  // Support vectors, coefficients and rho at full precision.
  nlohmann::json to_json() const;
  // Throws InputError naming `where` and the bad key.
  static SvrRegressor from_json(const nlohmann::json& j, const std::string& where);

 private:
  struct Model;
  explicit SvrRegressor(std::unique_ptr<Model> model);
  std::unique_ptr<Model> model_;
};

}  // namespace hystbench
