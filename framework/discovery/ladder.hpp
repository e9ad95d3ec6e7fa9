#pragma once
// Discovery: fit the start model, then repeat diagnose -> add the winner ->
// refit -> prune until the verdict is "none". Every rung of the ladder
// records the model, its parameters and its errors, so a reader sees the
// error fall effect by effect.
//
// Pruning: an effect just added may make one already there redundant (a
// Bouc-Wen oscillator explains the resonance an ARX block was fitted to).
// After each addition every other effect is tried out (removed and the rest
// polished); the removal that lowers the BIC most is made, and again, until
// no removal lowers it.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/discovery/diagnosis.hpp"

namespace hystbench {

struct LadderStep {
  Model model;
  Eigen::VectorXd x;
  FitErrors errors;
  double bic = 0.0;
  std::string added = {};                 // effect added at this step ("" for the start)
  std::vector<std::string> removed = {};  // effects the new one made redundant
  std::string evidence = {};              // why it was added
  nlohmann::json where = {};              // compare_signals of this step's fit
};

struct Ladder {
  std::vector<LadderStep> steps;
  std::vector<Diagnosis> diagnoses;  // one per step; the last says "none" or hit max_steps
  bool stopped_by_limit = false;

  std::vector<std::string> final_effects() const { return steps.back().model.effects(); }
};

struct DiscoverOptions {
  DiagnoseOptions diagnose;
  int max_steps = 8;   // effects added at most
  // After an effect is added: the winner's warm refit is polished again and
  // `refit_restarts` global restarts of the extended model compete with it.
  int refit_restarts = 1;
};

// `start` fitted from scratch (diagnose.fit restarts), then the loop.
// `on_step` (optional) is called after each rung, e.g. to print it.
Ladder discover(const Model& start, const ModelData& data, const DiscoverOptions& options,
                const std::function<void(const LadderStep&, const Diagnosis&)>& on_step = {});

}  // namespace hystbench
