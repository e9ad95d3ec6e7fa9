#pragma once
// Discovery: fit the start model, then repeat diagnose -> add the winner ->
// refit -> prune until the verdict is "none". Every rung of the ladder
// records the model, its parameters and its errors, so a reader sees the
// error fall effect by effect.
//
// Pruning (pruning.hpp): an effect just added may make one already there
// redundant (a Bouc-Wen oscillator explains the resonance an ARX block was
// fitted to). After each addition every other effect is tried out (removed
// and the rest polished); a model that fits worse than one of these
// sub-models is first refitted from its optimum (the nesting rule); the
// removal that lowers the BIC most is made, and again, until no removal
// lowers it. The effect just added is protected from this unless
// its refit left it doing nothing (neutral within noise, model_check.hpp):
// then the error fell because of the refit, not because of the effect, and
// the ladder says so instead of crediting it.
//
// A ladder is complete (completeness.hpp) only when its last rung's residual
// is white and at the noise estimate on the estimation and held-out data; a
// last verdict of "none" alone does not make it complete.
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/discovery/diagnosis.hpp"
#include "framework/discovery/pruning.hpp"
#include "framework/model/input_hold.hpp"

namespace hystbench {

struct LadderStep {
  Model model;
  Eigen::VectorXd x;
  FitErrors errors;
  double bic = 0.0;
  std::string added = {};                 // effect added at this step ("" for the start)
  std::vector<std::string> removed = {};  // effects the new one made redundant
  std::string evidence = {};              // why it was added
  std::string attribution = {};           // who made the removed effects redundant, or why
                                          // the added effect was dropped again
  std::vector<NestingRefit> nesting = {};     // the nesting rule's refits while pruning
  std::vector<TriedSubModel> sub_models = {};  // tried with one effect less (pruning.hpp)
};

// The rung a diagnosis examined: its model, its fit and that fit's errors.
LadderStep rung_of(const Diagnosis& d);

struct Ladder {
  std::vector<LadderStep> steps;
  std::vector<Diagnosis> diagnoses;  // one per step: diagnoses[k] examined steps[k]
  bool stopped_by_limit = false;
  // Diagnoses [0, restored) came from a checkpoint: their step folders were
  // written by the run that made them.
  std::size_t restored = 0;

  std::vector<std::string> final_effects() const { return steps.back().model.effects(); }
  // The last rung is complete (its diagnosis's completeness).
  const Completeness& completeness() const { return diagnoses.back().completeness; }
  bool finished() const;  // the last diagnosis named nothing, or the step limit was hit
};

struct DiscoverOptions {
  DiagnoseOptions diagnose;
  int max_steps = 8;   // effects added at most
  // After an effect is added: the winner's warm refit is polished again and
  // `refit_restarts` global restarts of the extended model compete with it.
  int refit_restarts = 1;
  int substeps = 0;  // of every model of the ladder (0: each effect's default)
  InputHold input_hold = InputHold::Spline;  // of every model of the ladder
};

// Called after every diagnosis with the ladder so far (its last step and
// diagnosis are the new ones): to print, and to write the step and a
// checkpoint.
using LadderObserver = std::function<void(const Ladder&)>;

// `start` fitted from scratch (diagnose.fit restarts), then the loop.
Ladder discover(const Model& start, const ModelData& data, const DiscoverOptions& options,
                const LadderObserver& on_step = {});

// Continues `ladder` (restored from a checkpoint: at least one step and
// diagnosis) exactly as the uninterrupted run would have.
Ladder resume_discover(Ladder ladder, const ModelData& data, const DiscoverOptions& options,
                       const LadderObserver& on_step = {});

}  // namespace hystbench
