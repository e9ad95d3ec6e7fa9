#include "framework/report/trial_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "framework/core/error.hpp"
#include "framework/stats/descriptive.hpp"
#include "framework/stats/rank_sum_test.hpp"
#include "framework/stats/runtime_measures.hpp"

namespace hystbench {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Final fitness of every trial; a failed one counts as +inf, so that it
// ranks last (tied with the other failures) instead of vanishing from the
// comparison and flattering its algorithm.
std::vector<double> finals(const std::vector<TrialResult>& trials) {
  std::vector<double> out;
  for (const auto& r : trials)
    out.push_back(r.failed() ? std::numeric_limits<double>::infinity() : r.best);
  return out;
}

std::size_t reference_index(const Experiment& e,
                            const std::vector<std::vector<TrialResult>>& results,
                            const std::string& reference) {
  check_reference(e, reference);
  if (!reference.empty())
    for (std::size_t a = 0; a < e.algorithms.size(); ++a)
      if (e.algorithms[a].label == reference) return a;
  std::size_t best = 0;
  double best_median = std::numeric_limits<double>::infinity();
  for (std::size_t a = 0; a < results.size(); ++a) {
    const auto f = finals(results[a]);
    if (f.empty()) continue;
    const double m = stats::median(f);
    if (m < best_median) best_median = m, best = a;
  }
  return best;
}

// A failed trial still spent its evaluations, so every trial counts in the
// runtime measures; a failed one never as a success, whatever it reached
// before failing.
std::vector<stats::TrialRecord> records(const std::vector<TrialResult>& trials) {
  std::vector<stats::TrialRecord> out;
  for (const auto& r : trials)
    out.push_back({r.evaluations, r.failed() ? std::vector<TracePoint>{} : r.trace});
  return out;
}

void add_runtime(AlgorithmStatistics& row, const std::vector<TrialResult>& trials,
                 std::optional<double> target) {
  row.trials = static_cast<long>(trials.size());
  if (!target || trials.empty()) {
    row.success_rate = row.ert = kNaN;
    return;
  }
  const auto recs = records(trials);
  row.success_rate = stats::success_rate(recs, *target);
  row.successes = std::lround(row.success_rate * double(recs.size()));
  row.ert = stats::expected_runtime(recs, *target);
}

std::optional<long> most_evaluations(const std::vector<std::vector<TrialResult>>& results) {
  long most = 0;
  for (const auto& trials : results)
    for (const auto& r : trials)
      if (!r.failed()) most = std::max(most, r.evaluations);
  return most > 0 ? std::optional<long>(most) : std::nullopt;
}

void add_snapshots(AlgorithmStatistics& row, const std::vector<TrialResult>& trials,
                   std::optional<long> budget) {
  std::vector<std::vector<double>> at(kSnapshotFractions.size());
  if (budget)
    for (const auto& r : trials) {
      if (r.failed()) continue;
      const auto s = stats::fixed_budget_snapshots(r.trace, *budget, kSnapshotFractions);
      for (std::size_t i = 0; i < s.size(); ++i) at[i].push_back(s[i]);
    }
  for (const auto& values : at)
    row.snapshot_medians.push_back(values.empty() ? kNaN : stats::median(values));
}

// Rank-sum test of the reference against every other algorithm, Holm over
// all of them: the marks say '+' or '-' only where the adjusted p < alpha.
void add_marks(CampaignStatistics& s, const std::vector<std::vector<TrialResult>>& results,
               std::size_t ref) {
  const auto reference = finals(results[ref]);
  std::vector<std::size_t> tested;
  std::vector<double> p;
  for (std::size_t a = 0; a < results.size(); ++a) {
    auto& row = s.rows[a];
    row.p_holm = kNaN;
    row.mark = a == ref ? ' ' : '=';
    const auto other = finals(results[a]);
    if (a == ref || other.empty() || reference.empty()) continue;
    tested.push_back(a);
    const auto test = stats::rank_sum_test(reference, other);
    p.push_back(test.p);
    row.p_exact = test.exact;
  }
  if (tested.empty()) return;
  const auto h = stats::holm(p, s.alpha);
  for (std::size_t i = 0; i < tested.size(); ++i) {
    auto& row = s.rows[tested[i]];
    row.p_holm = h.adjusted[i];
    // Holm rejects only where the raw p < alpha too, so the plain mark has
    // the direction.
    if (h.rejected[i])
      row.mark = static_cast<char>(
          stats::rank_sum_mark(reference, finals(results[tested[i]]), s.alpha));
  }
}

}  // namespace

void check_reference(const Experiment& e, const std::string& reference) {
  if (reference.empty()) return;
  std::string labels;
  for (const auto& spec : e.algorithms) {
    if (spec.label == reference) return;
    labels += (labels.empty() ? "" : ", ") + spec.label;
  }
  throw InputError("--reference " + reference + ": no algorithm has this label; use one of " +
                   labels);
}

std::optional<double> runtime_target(const Experiment& e, std::optional<double> noise_floor) {
  if (e.budget.target) return e.budget.target;
  if (noise_floor && std::isfinite(*noise_floor)) return 1.01 * *noise_floor;
  return std::nullopt;
}

CampaignStatistics campaign_statistics(const Experiment& e,
                                       const std::vector<std::vector<TrialResult>>& results,
                                       const std::string& reference,
                                       std::optional<double> noise_floor) {
  CampaignStatistics s;
  const std::size_t ref = reference_index(e, results, reference);
  s.reference = e.algorithms[ref].label;
  s.reference_chosen = !reference.empty();
  s.target = runtime_target(e, noise_floor);
  if (s.target) s.target_origin = e.budget.target ? "budget target" : "1.01 × noise floor";
  s.budget = e.budget.evaluations;
  if (!s.budget) {
    s.budget = most_evaluations(results);
    s.budget_from_trials = s.budget.has_value();
  }
  for (std::size_t a = 0; a < results.size(); ++a) {
    AlgorithmStatistics row;
    row.label = e.algorithms[a].label;
    row.reference = a == ref;
    add_runtime(row, results[a], s.target);
    add_snapshots(row, results[a], s.budget);
    s.rows.push_back(std::move(row));
  }
  add_marks(s, results, ref);
  return s;
}

}  // namespace hystbench
