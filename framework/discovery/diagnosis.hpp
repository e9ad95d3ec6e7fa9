#pragma once
// Which physical effect is the model missing? For every effect of the
// catalog not in the model, the extended model is refitted warm-started at
// the current fit (the new effect starts neutral, so the extended model
// starts exactly where the current one is) and the candidates are ranked by
// the drop in BIC, with the held-out error as a guard against over-fitting.
//
// Significance (docs/discovery.md#hystbench-diagnose): a candidate is
// significant when
//   ΔBIC = N·ln(SSE_new/SSE_old) + Δk·ln N  ≤  bic_threshold  (default −10:
//   "very strong" evidence on the Kass & Raftery scale, odds above 150:1),
// and, when samples are held out, its held-out RMSE is at least
// `heldout_gain` (default 1 %) below the current model's. N counts the
// estimation samples.
//
// Verdict (docs/discovery.md#hystbench-diagnose, the close call): among the
// significant candidates, the one with the lowest ΔBIC — unless another
// significant candidate has a held-out RMSE at least `heldout_gain` lower, in
// which case the held-out error decides (BIC is computed on the data the fit
// saw; the held-out error is the better guard against a candidate that only
// absorbs the fit's own errors). Either way, when the two criteria disagree
// or the runner-up's ΔBIC is within `close_margin` of the winner's, the
// diagnosis is marked a close call and both candidates, with their fitted
// parameters, are shown.
// "none" when no candidate is significant — which is what a model with a
// white residual at the noise floor must get — or when the winner helps only
// in part: while the fit is above the noise floor, the winner must remove a
// quarter of what is left above it on the held-out data (beyond_catalog.hpp;
// the diagnosis then says what it refused and why).
//
// Before any candidate is tried, the current fit is checked for being off
// its optimum (fit_at_optimum.hpp), and the diagnosis reports whether the
// model is complete (completeness.hpp) and what its parameters look like
// (model_check.hpp).
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/discovery/beyond_catalog.hpp"
#include "framework/discovery/comparison.hpp"
#include "framework/discovery/completeness.hpp"
#include "framework/discovery/fit_at_optimum.hpp"
#include "framework/discovery/fit_errors.hpp"
#include "framework/discovery/model_check.hpp"
#include "framework/discovery/model_fit.hpp"

namespace hystbench {

struct DiagnoseOptions {
  FitOptions fit;
  std::vector<std::string> candidates;  // empty: every registered effect not in the model
  std::vector<std::string> exclude;     // never tried (discover: an effect just dropped again)
  double bic_threshold = -10.0;
  double heldout_gain = 0.01;
  double close_margin = 10.0;  // ΔBIC units: "very strong" on the Kass & Raftery scale
  // Global restarts of every extended model that compete with its warm
  // refit: a fit stuck in a poor basin can hide what an effect would give.
  // Skipped when the current residual is white and uncorrelated with the input.
  int candidate_restarts = 1;
  std::string u_unit, y_unit;  // for the evidence sentences and the breakdowns

  nlohmann::json to_json() const;
};

struct Candidate {
  std::string effect;
  Model model;
  Eigen::VectorXd x;
  FitErrors after;
  int delta_k = 0;
  double delta_bic = 0.0;
  bool significant = false;
  std::string evidence = {};  // one plain sentence
  ModelCheck check = {};      // its fitted parameters, with standard errors
};

struct CloseCall {
  bool close = false;
  std::string reason;     // why it is a close call, and which rule decided
  std::string runner_up;  // the other candidate
};

struct Diagnosis {
  Model model;  // the model as diagnosed (polished)
  Eigen::VectorXd x;
  FitErrors errors;
  double bic = 0.0;
  std::vector<Candidate> candidates = {};  // best first
  std::string verdict = {};                // an effect name or "none"
  CloseCall close_call = {};
  OptimumCheck optimum = {};               // done before the candidates
  Completeness completeness = {};          // of the current fit
  ModelCheck check = {};                   // of the current fit
  Comparison where = {};                   // compare_signals of the current fit
  BeyondCatalog beyond = {};               // when something systematic is left that no effect captures
  nlohmann::json options = {};

  const Candidate* winner() const;
  const Candidate* find(const std::string& effect) const;
  // {"verdict", "complete", "completeness", "close_call", "optimum", "model",
  //  "parameters", "candidates": [...], "where", "errors", "bic", "options",
  //  "beyond_catalog"}
  nlohmann::json to_json() const;
};

// The effects a diagnosis of `model` tries: options.candidates, or by
// default every registered effect, less those the model has, those in
// options.exclude and, by default, those whose role the model already holds
// (an effect that replaces msd beside another: it would be a second
// resonance in series, second_mode's role).
std::vector<std::string> candidate_effects(const Model& model, const DiagnoseOptions& options);

// BIC of a fit with `k` parameters: N ln(SSE/N) + k ln N over the
// estimation samples.
double bic(double sse, long n, int k);

// Diagnoses the fitted model (model, x): polishes it once more, checks that
// it is at its optimum (restarts when not), then tries each candidate (in
// parallel). `status` is told what is being tried.
Diagnosis diagnose(const Model& model, const Eigen::VectorXd& x, const ModelData& data,
                   const DiagnoseOptions& options);

// The verdict and close call of `d` from its (sorted) candidates.
void decide(Diagnosis& d, const DiagnoseOptions& options);

}  // namespace hystbench
