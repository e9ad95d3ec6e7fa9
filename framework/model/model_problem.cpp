#include "framework/model/model_problem.hpp"

#include "framework/model/lane_squared_error.hpp"

#include <omp.h>

#include <algorithm>
#include <limits>

namespace hystbench {
namespace {

// An output finite but beyond 1e154 squares to inf, and inf times a held-out
// sample's weight 0 is NaN: such a candidate has diverged, and its SSE is
// infinite, never NaN, which an optimizer cannot rank.
double sse_or_infinite(double sum) {
  constexpr double kInfinite = std::numeric_limits<double>::infinity();
  return sum < kInfinite ? sum : kInfinite;
}

}  // namespace

// A held start searches its level for each candidate (held_start.hpp), so
// such candidates run one at a time.
ModelProblem::ModelProblem(const Model& model, const ModelData& data)
    : model_(model), data_(data), bounds_(model.bounds()), batched_(model.has_lanes() && !data.held_start) {}

double ModelProblem::sse(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  Eigen::VectorXd y;
  if (!model_.simulate(x, data_, y)) return std::numeric_limits<double>::infinity();
  return sse_of(y);
}

double ModelProblem::sse_of(const Eigen::VectorXd& y) const {
  return sse_or_infinite(((data_.y - y).array().square() * data_.estimation.array()).sum());
}

void ModelProblem::evaluate(const Eigen::Ref<const Eigen::MatrixXd>& X,
                            Eigen::Ref<Eigen::VectorXd> f) const {
  const Eigen::Index n = X.cols();
  if (!batched_) {
#pragma omp parallel for schedule(dynamic) if (n > 1)
    for (Eigen::Index j = 0; j < n; ++j) f[j] = sse(X.col(j));
    return;
  }
  const Eigen::Index blocks = (n + kEffectLanes - 1) / kEffectLanes;
#pragma omp parallel for schedule(dynamic) if (blocks > 1)
  for (Eigen::Index b = 0; b < blocks; ++b) evaluate_block(X, b * kEffectLanes, f);
}

void ModelProblem::evaluate_block(const Eigen::Ref<const Eigen::MatrixXd>& X, Eigen::Index first,
                                  Eigen::Ref<Eigen::VectorXd> f) const {
  const Eigen::Index count = std::min<Eigen::Index>(kEffectLanes, X.cols() - first);
  // A partial block repeats its last candidate in the spare lanes.
  Eigen::MatrixXd block(X.rows(), kEffectLanes);
  for (Eigen::Index l = 0; l < kEffectLanes; ++l) block.col(l) = X.col(first + std::min(l, count - 1));
  LaneSquaredError sse(data_.y, data_.estimation);
  LaneMask ok;
  model_.simulate_lanes(block, data_, ok,
                        [&](Eigen::Index begin, std::span<const LaneVector> y) { sse.add(begin, y); });
  const auto sums = sse.sums();
  for (Eigen::Index l = 0; l < count; ++l)
    f[first + l] = ok[l] ? sse_or_infinite(sums[std::size_t(l)]) : std::numeric_limits<double>::infinity();
}

nlohmann::json ModelProblem::describe() const {
  return {{"name", name()},
          {"fitness", "SSE"},
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
