#include "framework/control/control_run.hpp"

#include <atomic>
#include <cmath>
#include <limits>

#include "framework/control/uncontrolled.hpp"
#include "framework/core/parallel_jobs.hpp"
#include "framework/core/rng.hpp"

namespace hystbench {
namespace {

std::uint64_t noise_seed(const ControlExperiment& x, int trial) {
  return trial_seed(x.seed, "sensor noise", std::uint64_t(trial));
}

MetricSummary summarise(const std::vector<TrialOutcome>& trials, bool truth) {
  MetricSummary s;
  for (const auto& [name, f] : kSuppressionMetrics) {
    double sum = 0.0, sum_sq = 0.0;
    int n = 0;
    for (const auto& t : trials) {
      const double v = (truth ? t.truth : t.measured).*f;
      if (!std::isnan(t.diverged_at_s) || std::isnan(v)) continue;
      sum += v;
      ++n;
    }
    const double mean = n ? sum / n : std::numeric_limits<double>::quiet_NaN();
    for (const auto& t : trials) {
      const double v = (truth ? t.truth : t.measured).*f;
      if (std::isnan(t.diverged_at_s) && !std::isnan(v)) sum_sq += (v - mean) * (v - mean);
    }
    s.mean.*f = mean;
    s.sd.*f = n > 1 ? std::sqrt(sum_sq / (n - 1)) : 0.0;
  }
  for (const auto& t : trials)
    if (std::isnan(t.diverged_at_s) && std::isnan((truth ? t.truth : t.measured).convergence_s))
      ++s.never_converged;
  return s;
}

void summarise(ControllerResult& r) {
  r.earliest_divergence_s = std::numeric_limits<double>::quiet_NaN();
  for (const auto& t : r.trials) {
    if (std::isnan(t.diverged_at_s)) continue;
    ++r.diverged_trials;
    if (!(t.diverged_at_s >= r.earliest_divergence_s)) r.earliest_divergence_s = t.diverged_at_s;
  }
  r.measured = summarise(r.trials, false);
  r.truth = summarise(r.trials, true);
}

ControllerResult uncontrolled_result(const ControlExperiment& x, std::vector<LoopTrace>& off) {
  ControllerResult r;
  r.entry.label = "uncontrolled";
  for (const auto& t : off)
    r.trials.push_back({suppression_metrics(t.error, t.error, x.windows),
                        suppression_metrics(t.true_error, t.true_error, x.windows), t.diverged_at_s});
  r.first_trial = std::move(off[0]);
  summarise(r);
  return r;
}

}  // namespace

ControlResults run_control(const ControlExperiment& x, const ControlSetup& setup,
                           const std::function<void(int, int)>& progress) {
  const int trials = x.trials, controllers = int(x.controllers.size());
  const int total = trials * (controllers + 1);
  std::atomic<int> done{0};
  auto tick = [&] { progress(++done, total); };

  std::vector<LoopTrace> off(trials);
  parallel_jobs(std::size_t(trials), [&](std::size_t t) {
    off[t] = run_uncontrolled(setup.paths, setup.loop, noise_seed(x, int(t)));
    tick();
  });

  ControlResults results;
  results.controllers.resize(controllers);
  for (int c = 0; c < controllers; ++c) {
    results.controllers[c].entry = x.controllers[c];
    results.controllers[c].estimate = &setup.estimate_for(std::size_t(c));
    results.controllers[c].trials.resize(trials);
  }
  parallel_jobs(std::size_t(controllers * trials), [&](std::size_t job) {
    const int c = int(job) / trials, t = int(job) % trials;
    auto controller = x.controllers[c].make();
    LoopTrace trace = run_loop(setup.paths, *setup.estimate_for(c).stream, *controller, setup.loop,
                               noise_seed(x, t));
    TrialOutcome& o = results.controllers[c].trials[t];
    o.diverged_at_s = trace.diverged_at_s;
    if (!trace.diverged()) {
      o.measured = suppression_metrics(trace.error, off[t].error, x.windows);
      o.truth = suppression_metrics(trace.true_error, off[t].true_error, x.windows);
    }
    if (t == 0) results.controllers[c].first_trial = std::move(trace);
    tick();
  });
  for (auto& r : results.controllers) summarise(r);
  results.uncontrolled = uncontrolled_result(x, off);
  return results;
}

}  // namespace hystbench
