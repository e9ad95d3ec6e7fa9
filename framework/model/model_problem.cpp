#include "framework/model/model_problem.hpp"

#include <omp.h>

#include <limits>

namespace hystbench {

ModelProblem::ModelProblem(const Model& model, const ModelData& data)
    : model_(model), data_(data), bounds_(model.bounds()) {}

double ModelProblem::sse(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  Eigen::VectorXd y;
  if (!model_.simulate(x, data_, y)) return std::numeric_limits<double>::infinity();
  return ((data_.y - y).array().square() * data_.estimation.array()).sum();
}

void ModelProblem::evaluate(const Eigen::Ref<const Eigen::MatrixXd>& X,
                            Eigen::Ref<Eigen::VectorXd> f) const {
  const Eigen::Index n = X.cols();
#pragma omp parallel for schedule(dynamic) if (n > 1)
  for (Eigen::Index j = 0; j < n; ++j) f[j] = sse(X.col(j));
}

nlohmann::json ModelProblem::describe() const {
  return {{"name", name()},
          {"samples", data_.size()},
          {"estimation_samples", data_.estimation_count()},
          {"parameters", bounds_.names}};
}

SubspaceProblem::SubspaceProblem(const Problem& full, Eigen::VectorXd base, std::vector<int> free)
    : full_(full), base_(std::move(base)), free_(std::move(free)) {
  const Bounds& b = full.bounds();
  bounds_.lower.resize(free_.size());
  bounds_.upper.resize(free_.size());
  for (std::size_t i = 0; i < free_.size(); ++i) {
    bounds_.lower[i] = b.lower[free_[i]];
    bounds_.upper[i] = b.upper[free_[i]];
    bounds_.names.push_back(b.names[free_[i]]);
  }
}

Eigen::VectorXd SubspaceProblem::expand(const Eigen::Ref<const Eigen::VectorXd>& z) const {
  Eigen::VectorXd x = base_;
  for (std::size_t i = 0; i < free_.size(); ++i) x[free_[i]] = z[i];
  return x;
}

void SubspaceProblem::evaluate(const Eigen::Ref<const Eigen::MatrixXd>& Z,
                               Eigen::Ref<Eigen::VectorXd> f) const {
  Eigen::MatrixXd X(base_.size(), Z.cols());
  for (Eigen::Index j = 0; j < Z.cols(); ++j) X.col(j) = expand(Z.col(j));
  full_.evaluate(X, f);
}

}  // namespace hystbench
