#pragma once
// Controller tuning as an optimization problem (docs/control.md#tuning), so
// that `hystbench run` compares every optimizer plugin on it. The decision
// variables are constants of one controller; the fitness of a candidate is
// one closed-loop run of a control experiment with a fixed noise seed:
//
//   f = A_on / A_off + convergence_weight * t_conv
//
// A = RMS of the true error over the steady window (A_off from the
// uncontrolled run with the same noise), t_conv the convergence time in
// seconds (the run's length when it never converges); +inf when the loop
// diverges. Experiment file:
//
//   "problem": {"type": "control",
//               "experiment": "benchmarks/experiments/avc_beam.json",
//               "controller": "vss_fxlms", "params": {...fixed...},
//               "tune": [{"param": "gamma", "lower": 1e-6, "upper": 1e-3, "scale": "log"},
//                        {"param": "mu_max", "lower": 0.003, "upper": 0.1, "scale": "log"}],
//               "convergence_weight": 0.001, "noise_seed": 1, "duration_s": 30}
//
// A "log" parameter is searched as its log10 (bounds and names say so).
// Only real-valued constants can be tuned. The loop uses the experiment's
// own secondary-path estimate; estimates named by its controllers are not
// used here.
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/control/control_setup.hpp"
#include "framework/core/problem.hpp"
#include "framework/core/registry.hpp"

namespace hystbench {

class ControlProblem : public Problem {
 public:
  static ProblemInfo info();
  // Throws InputError naming the key (problem.tune[1].param, ...).
  ControlProblem(const Params& options, const std::filesystem::path& base_dir);

  std::string name() const override;
  const Bounds& bounds() const override { return bounds_; }
  void evaluate(const Eigen::Ref<const Eigen::MatrixXd>& X, Eigen::Ref<Eigen::VectorXd> f) const override;
  nlohmann::json describe() const override;

  // The controller's parameters for candidate x (log parameters raised).
  nlohmann::json params_of(const Eigen::Ref<const Eigen::VectorXd>& x) const;
  double fitness(const Eigen::Ref<const Eigen::VectorXd>& x) const;

 private:
  struct Tuned {
    std::string param;
    bool log = false;
  };

  ControlExperiment experiment_;
  ControlSetup setup_;
  std::string controller_;
  nlohmann::json fixed_;
  std::vector<Tuned> tuned_;
  Bounds bounds_;
  double convergence_weight_ = 1e-3;
  std::uint64_t noise_seed_ = 1;
  LoopTrace uncontrolled_;
};

}  // namespace hystbench
