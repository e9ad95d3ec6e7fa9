#pragma once
// `hystbench track` without its files: the nominal model, the uncertainty
// weight, the H∞ design and the check of the seed's printed numbers, then
// every (reference, controller) run in parallel (docs/tracking.md).
#include <functional>
#include <string>
#include <vector>

#include "framework/tracking/hinf_design.hpp"
#include "framework/tracking/nominal_dynamics.hpp"
#include "framework/tracking/seed_numbers.hpp"
#include "framework/tracking/tracking_experiment.hpp"
#include "framework/tracking/tracking_loop.hpp"
#include "framework/tracking/uncertainty_weight.hpp"

namespace hystbench {

struct TrackingRow {
  const TrackingReference* reference = nullptr;
  const TrackingController* controller = nullptr;
  TrackingRun run;
  // Empty when the run is sound; else why its numbers need care (the
  // reference leaves the reachable range, the amplifier limited the drive,
  // the loop diverged).
  std::string status;
};

struct TrackingResults {
  NominalDynamics nominal;
  UncertaintyWeight uncertainty;
  ControllerDesign design;
  SeedNumbersCheck seed_check;
  double reachable_low = 0.0, reachable_high = 0.0;  // the identified model's output over the amplifier's range
  std::vector<TrackingRow> rows;                     // reference-major
  double design_seconds = 0.0, seconds = 0.0;
};

// The nominal model, the weights, the controllers (filled into x's H∞
// controllers) and the checks that need no run. Throws InputError naming
// why when the design is impossible: before anything is written.
TrackingResults design_tracking(TrackingExperiment& x);

// Every (reference, controller) run, in parallel; `progress` gets short
// status texts.
void run_tracking_rows(const TrackingExperiment& x, TrackingResults& r,
                       const std::function<void(const std::string&)>& progress);

}  // namespace hystbench
