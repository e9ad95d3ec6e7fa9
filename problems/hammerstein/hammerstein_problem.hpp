#pragma once
// The Hammerstein identification problem: find the 13 seed-model parameters
// that minimise the SSE between model and measurement.
//
// Experiment JSON:
//   {"type": "hammerstein",
//    "data": "problems/hammerstein/data/default.csv",
//    "columns": {"t": "t_s", "u": "u_N", "y": "y_m"},     optional
//    "bouc_wen_form": "increment" | "paper",               optional
//    "bounds": {"beta": [0, 0.02], ...},                   optional overrides
//    "units": {"u": "V", "y": "µm"}}                        optional, for figures
//
// When a file DATA.truth.json sits beside DATA.csv (as `hystbench simulate`
// writes it), its noise-floor SSE is reported with the results, and its
// units are used unless the experiment names others.
#include <optional>

#include "framework/core/problem.hpp"
#include "framework/core/registry.hpp"
#include "framework/io/measurement.hpp"
#include "problems/hammerstein/hammerstein_model.hpp"

namespace hystbench {

class HammersteinProblem : public Problem, public SignalModelProblem, public LeastSquaresProblem {
 public:
  struct Units {
    std::string u, y;
  };
  // `noise_floor`: SSE of the true parameters, when known (reported with results).
  HammersteinProblem(Measurement data, BoucWenForm form, Bounds bounds, Units units = {},
                     std::optional<double> noise_floor = std::nullopt);

  static ProblemInfo info();  // registry entry "hammerstein"
  // The documented default search box (docs/usage.md#hammerstein--the-mfc-seed-model).
  static Bounds default_bounds();

  std::string name() const override;
  const Bounds& bounds() const override { return bounds_; }
  // Batched and vectorised (batched_sse.hpp); each value equals
  // hammerstein_sse() of its column bit for bit. evaluate() uses one thread.
  void evaluate(const Eigen::Ref<const Eigen::MatrixXd>& X,
                Eigen::Ref<Eigen::VectorXd> f) const override;
  void evaluate_with(const Eigen::Ref<const Eigen::MatrixXd>& X, Eigen::Ref<Eigen::VectorXd> f,
                     const EvaluationOptions& options) const override;
  nlohmann::json describe() const override;

  const Eigen::VectorXd& time() const override { return data_.t; }
  const Eigen::VectorXd& input() const override { return data_.u; }
  const Eigen::VectorXd& measured() const override { return data_.y; }
  const std::vector<std::string>& segments() const override { return data_.segment; }
  Eigen::VectorXd simulate(const Eigen::Ref<const Eigen::VectorXd>& x) const override;
  // r = y - simulate(x): what the Levenberg-Marquardt polish works on.
  Eigen::Index residual_count() const override { return data_.y.size(); }
  void residuals(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> r) const override;
  std::string input_unit() const override { return units_.u; }
  std::string output_unit() const override { return units_.y; }

  std::optional<double> noise_floor() const { return noise_floor_; }

 private:
  Measurement data_;
  BoucWenForm form_;
  Bounds bounds_;
  std::optional<double> noise_floor_;
  Units units_;
};

}  // namespace hystbench
