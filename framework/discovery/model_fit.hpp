#pragma once
// Fitting a discovery model to a measurement: seeded global restarts, each
// polished by an NLopt local method, best estimation SSE wins; and the warm
// refit that diagnosis uses when it tries one more effect.
//
// Every evaluation goes through an EvaluationContext, so budgets and seeds
// work as in benchmark trials; the held-out samples never enter a fitness.
#include "framework/core/eigen.hpp"
#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/model/model.hpp"

namespace hystbench {

struct FitOptions {
  // Any registered optimizer. jSO by default: on discovery models (Bouc-Wen
  // loops with unstable regions in the box) it reached the optimum in every
  // restart where CMA-ES stalled (docs/discovery.md#hystbench-fit).
  std::string optimizer = "jso";
  nlohmann::json optimizer_params = nlohmann::json::object();
  long evaluations = 0;  // global stage per restart; 0 = 2500 per parameter, at least 10000
  int restarts = 3;      // global restarts (a warm start, when given, comes on top)
  std::string local = "LN_BOBYQA";  // NLopt local method of the polish
  long local_evaluations = 0;       // polish per start; 0 = 300 per parameter, at least 1000
  std::uint64_t seed = 1;
  // The global stages (restarts, and the search of a new effect's
  // parameters in a warm refit) may see a coarser problem than the polish:
  // ODE sub-steps (0: the model's own) and the leading samples of the record
  // (0: all; the whole record when they do not reach its input range, see
  // screening_length). The new effect's search spends this many evaluations
  // per new parameter (at least 1000 in all).
  long screening_per_parameter = 1000;
  int screening_substeps = 5;
  Eigen::Index screening_samples = 16384;
  // Called with a short status ("restart 2/3", ...); may be empty.
  std::function<void(const std::string&)> status;

  long global_budget(int dimension) const;
  long local_budget(int dimension) const;
  // Checks the optimizer name and parameters and the local method; throws
  // InputError naming the bad option.
  void validate() const;
  nlohmann::json to_json() const;
};

struct FitResult {
  Model model;
  Eigen::VectorXd x;  // normalised parameters
  double sse = 0.0;   // normalised estimation SSE
  long evaluations = 0;
  double seconds = 0.0;
  std::vector<double> start_sse;  // best SSE of every start, in order
};

// The leading samples stand for the record in a global search when their
// input spread (0.5 % to 99.5 % quantile range) is at least this share of
// the whole record's. On the measured records at hand the heads reach 0.999
// to 1.002 of it, and Silverbox's arrow, whose amplitude grows, 0.41.
inline constexpr double kScreeningSpread = 0.9;

// How many leading samples the global stages see: options.screening_samples
// when they reach the record's input range, else the whole record.
Eigen::Index screening_length(const ModelData& data, const FitOptions& options);

// Global fit with restarts. `warm` (optional) is one more start, polished
// locally before the global restarts.
FitResult fit_model(const Model& model, const ModelData& data, const FitOptions& options,
                    const Eigen::VectorXd* warm = nullptr);

// Refit of `model` from `x0` in which the parameters `fresh` (a newly added
// effect, at its neutral value in x0) are first searched globally with the
// others held, then everything is polished. Never worse than x0.
FitResult refit_warm(const Model& model, const ModelData& data, const Eigen::VectorXd& x0,
                     const std::vector<int>& fresh, const FitOptions& options);

}  // namespace hystbench
