#pragma once
// Which physical effect is the model missing? For every effect of the
// catalog not in the model, the extended model is refitted warm-started at
// the current fit (the new effect starts neutral, so the extended model
// starts exactly where the current one is) and the candidates are ranked by
// the drop in BIC, with the held-out error as a guard against over-fitting.
//
// Significance (documented in the README): a candidate is significant when
//   ΔBIC = N·ln(SSE_new/SSE_old) + Δk·ln N  ≤  bic_threshold  (default −10:
//   "very strong" evidence on the Kass & Raftery scale, odds above 150:1),
// and, when samples are held out, its held-out RMSE is at least
// `heldout_gain` (default 1 %) below the current model's. N counts the
// estimation samples. The verdict is the best significant candidate, or
// "none" — which is what a model with a white residual at the noise floor
// must get.
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/discovery/fit_errors.hpp"
#include "framework/discovery/model_fit.hpp"

namespace hystbench {

struct DiagnoseOptions {
  FitOptions fit;
  std::vector<std::string> candidates;  // empty: every registered effect not in the model
  double bic_threshold = -10.0;
  double heldout_gain = 0.01;
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
};

struct Diagnosis {
  Model model;  // the model as diagnosed (polished)
  Eigen::VectorXd x;
  FitErrors errors;
  double bic = 0.0;
  std::vector<Candidate> candidates = {};  // best first
  std::string verdict = {};                // an effect name or "none"
  nlohmann::json where = {};               // compare_signals of the current fit
  nlohmann::json options = {};

  const Candidate* winner() const;
  // {"verdict", "model", "candidates": [...], "where", "errors", "bic", "thresholds"}
  nlohmann::json to_json() const;
};

// BIC of a fit with `k` parameters: N ln(SSE/N) + k ln N over the
// estimation samples.
double bic(double sse, long n, int k);

// Diagnoses the fitted model (model, x): polishes it once more so that every
// candidate is compared with a converged fit, then tries each candidate
// (in parallel). `status` is told what is being tried.
Diagnosis diagnose(const Model& model, const Eigen::VectorXd& x, const ModelData& data,
                   const DiagnoseOptions& options);

}  // namespace hystbench
