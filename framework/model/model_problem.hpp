#pragma once
// Fitting a discovery model as an optimisation problem: the bounds are the
// model's normalised parameter box and the fitness is the sum of squared
// errors of the normalised output over the estimation samples only.
#include <string>
#include <vector>

#include "framework/core/problem.hpp"
#include "framework/model/model.hpp"

namespace hystbench {

class ModelProblem : public Problem {
 public:
  // Keeps references: `model` and `data` must outlive the problem.
  ModelProblem(const Model& model, const ModelData& data);

  std::string name() const override { return "model(" + model_.text() + ")"; }
  const Bounds& bounds() const override { return bounds_; }
  // Candidates are simulated in blocks of kEffectLanes when every effect of
  // the model has a batched form (effect_lanes.hpp), one at a time
  // otherwise; blocks or candidates run in parallel (OpenMP; nested inside
  // the parallel candidates of a diagnosis when nesting is enabled, so that
  // the last long-running candidate still uses every core). Each value
  // equals sse() of its column bit for bit, whatever the path and thread.
  void evaluate(const Eigen::Ref<const Eigen::MatrixXd>& X,
                Eigen::Ref<Eigen::VectorXd> f) const override;
  nlohmann::json describe() const override;

  // Estimation SSE of one candidate (+inf when unstable).
  double sse(const Eigen::Ref<const Eigen::VectorXd>& x) const;
  // Whether evaluate() simulates blocks of candidates.
  bool batched() const { return batched_; }

 private:
  // Summed by Eigen; blocks copy its order (lane_squared_error.hpp): change
  // the expression and both must change together.
  double sse_of(const Eigen::VectorXd& y) const;
  // Candidates first .. first + kEffectLanes - 1 (fewer at the end) into f.
  void evaluate_block(const Eigen::Ref<const Eigen::MatrixXd>& X, Eigen::Index first,
                      Eigen::Ref<Eigen::VectorXd> f) const;

  const Model& model_;
  const ModelData& data_;
  Bounds bounds_;
  bool batched_;
};

// The same problem seen through a subset of its parameters: the others stay
// at `base`. Used to search a newly added effect before polishing all.
class SubspaceProblem : public Problem {
 public:
  SubspaceProblem(const Problem& full, Eigen::VectorXd base, std::vector<int> free);

  std::string name() const override { return full_.name() + "[subspace]"; }
  const Bounds& bounds() const override { return bounds_; }
  void evaluate(const Eigen::Ref<const Eigen::MatrixXd>& X,
                Eigen::Ref<Eigen::VectorXd> f) const override;

  // The full parameter vector for subspace point z.
  Eigen::VectorXd expand(const Eigen::Ref<const Eigen::VectorXd>& z) const;

 private:
  const Problem& full_;
  Eigen::VectorXd base_;
  std::vector<int> free_;
  Bounds bounds_;
};

}  // namespace hystbench
