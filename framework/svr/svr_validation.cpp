#include "framework/svr/svr_validation.hpp"

namespace hystbench {

double blocked_cv_error(const Eigen::MatrixXd& rows, const Eigen::VectorXd& targets,
                        const SvrHyperparameters& h, int folds) {
  const Eigen::Index n = rows.rows();
  double sum = 0.0;
  for (int f = 0; f < folds; ++f) {
    const Eigen::Index begin = n * f / folds, end = n * (f + 1) / folds;
    Eigen::MatrixXd train(n - (end - begin), rows.cols());
    Eigen::VectorXd train_targets(train.rows());
    train << rows.topRows(begin), rows.bottomRows(n - end);
    train_targets << targets.head(begin), targets.tail(n - end);
    const SvrRegressor svr = SvrRegressor::train(train, train_targets, h, "problem");
    for (Eigen::Index r = begin; r < end; ++r) {
      const double e = svr.predict(rows.row(r).transpose()) - targets[r];
      sum += e * e;
    }
  }
  return sum / double(n);
}

}  // namespace hystbench
