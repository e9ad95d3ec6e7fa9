#include "framework/tracking/tracking_run.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>

#include "framework/core/parallel_jobs.hpp"
#include "framework/core/rng.hpp"
#include "framework/control/model_stream.hpp"
#include "framework/core/text.hpp"

namespace hystbench {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The identified model's output on a steady loop: three slow sweeps of the
// amplifier's range up and down (2 s each at the loop's rate), the range of
// the last. Hysteresis leaves the output above its rest value at the lowest
// input once the actuator has been driven, so the first sweep overstates it.
void reachable_range(const TrackingExperiment& x, TrackingResults& r) {
  auto model = x.identified_model->clone();
  const long half = std::lround(1.0 / x.sample_time), cycle = 2 * half;
  r.reachable_low = std::numeric_limits<double>::infinity();
  r.reachable_high = -r.reachable_low;
  for (long k = 0; k < 3 * cycle; ++k) {
    const long phase = k % cycle;
    const double share = double(phase <= half ? phase : cycle - phase) / double(half);
    const double y = model->step_back(model->step_front(x.u_min + share * (x.u_max - x.u_min)));
    if (k < 2 * cycle) continue;
    r.reachable_low = std::min(r.reachable_low, y);
    r.reachable_high = std::max(r.reachable_high, y);
  }
}

void design(TrackingExperiment& x, TrackingResults& r) {
  r.nominal = identify_dynamics(*x.identified_model, x.sample_time, x.p, x.q, x.seed, "nominal");
  const UncertaintySpec& u = x.uncertainty;
  if (u.kind == "seed")
    r.uncertainty = seed_uncertainty_weight();
  else if (u.kind == "given")
    r.uncertainty = given_uncertainty_weight(u.num, u.den, "uncertainty");
  else
    r.uncertainty = residual_uncertainty_weight(x.identified, u.records, u.margin, u.rise, "uncertainty");
  r.design = design_controller(r.nominal, r.uncertainty, x.design);
  for (TrackingController& c : x.controllers)
    if (c.kind == TrackingController::Kind::Hinf)
      c.feedback = c.order == "full" ? r.design.full_discrete : r.design.reduced_discrete;
  r.seed_check = check_seed_numbers();
  reachable_range(x, r);
  // Refuses a front that cannot be inverted now rather than after the first run.
  InverseCompensator(*x.identified_model, x.identified.description, x.u_min, x.u_max, x.inverse_tolerance);
}

std::string status_of(const TrackingRow& row, const TrackingResults& r, const std::string& unit) {
  const TrackingReference& ref = *row.reference;
  if (!row.run.finite) return "the loop diverged";
  if (ref.lowest() < r.reachable_low || ref.highest() > r.reachable_high)
    return "out of range: the reference spans " + format_number("%.3g", ref.lowest()) + " to " +
           format_number("%.3g", ref.highest()) + " " + unit + ", the identified model reaches " +
           format_number("%.3g", r.reachable_low) + " to " + format_number("%.3g", r.reachable_high) + " " + unit +
           " (seed 002, Remark 1)";
  const long scored = row.run.window.end() - row.run.window.begin;
  if (row.run.saturated_in_window > 0)
    return "the amplifier limited " +
           format_number("%.2g", 100.0 * double(row.run.saturated_in_window) / double(scored)) +
           " % of the scored samples";
  return "";
}

}  // namespace

TrackingResults design_tracking(TrackingExperiment& x) {
  const auto start = Clock::now();
  TrackingResults r;
  design(x, r);
  r.design_seconds = seconds_since(start);
  return r;
}

void run_tracking_rows(const TrackingExperiment& x, TrackingResults& r,
                       const std::function<void(const std::string&)>& progress) {
  const auto start = Clock::now();
  const ModelStream plant = model_stream(x.plant, x.base_dir, x.sample_time, "plant");
  const InverseCompensator inverse(*x.identified_model, x.identified.description, x.u_min, x.u_max,
                                   x.inverse_tolerance);
  const TrackingSetup setup{x.sample_time, plant.stream.get(), &inverse, &r.nominal.feedforward, x.sensor};
  r.rows.clear();
  for (const TrackingReference& ref : x.references)
    for (const TrackingController& c : x.controllers) r.rows.push_back({&ref, &c, {}, ""});
  std::atomic<int> done{0};
  const int total = int(r.rows.size());
  parallel_jobs(r.rows.size(), [&](std::size_t i) {
    TrackingRow& row = r.rows[i];
    // One noise sequence per reference: the controllers see the same sensor.
    const std::uint64_t seed = splitmix64(x.seed + i / x.controllers.size());
    row.run = run_tracking(setup, *row.controller, *row.reference, x.window, seed);
    row.status = status_of(row, r, x.y_unit);
    const int finished = ++done;
#pragma omp critical(tracking_progress)
    progress("run " + std::to_string(finished) + "/" + std::to_string(total));
  });
  r.seconds = r.design_seconds + seconds_since(start);
}

}  // namespace hystbench
