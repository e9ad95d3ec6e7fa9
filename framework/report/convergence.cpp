#include "framework/report/convergence.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "framework/io/atomic_file.hpp"
#include "framework/io/csv_format.hpp"
#include "framework/stats/descriptive.hpp"
#include "framework/stats/runtime_measures.hpp"

namespace hystbench {
namespace {


long last_evaluation(const TrialResult& r) {
  const long traced = r.trace.empty() ? 0 : r.trace.back().evaluations;
  return std::max(r.evaluations, traced);
}

// Log-spaced so that the early, fast-moving part of a run is resolved as
// well as the long tail; rounding to whole evaluations can repeat a value,
// so repeats are dropped.
std::vector<long> log_grid(long last, int points) {
  std::vector<long> grid;
  if (last < 1) return grid;
  const int n = std::max(points, 2);
  const double log_last = std::log(double(last));
  for (int i = 0; i < n; ++i) {
    const long v = std::clamp(std::lround(std::exp(log_last * i / (n - 1))), 1L, last);
    if (grid.empty() || v > grid.back()) grid.push_back(v);
  }
  if (grid.back() != last) grid.push_back(last);
  return grid;
}

}  // namespace

ConvergenceCurve convergence_curve(const std::string& label,
                                   const std::vector<TrialResult>& trials, int points) {
  std::vector<const TrialResult*> ok;
  long last = 0;
  for (const auto& r : trials) {
    if (r.failed()) continue;
    ok.push_back(&r);
    last = std::max(last, last_evaluation(r));
  }
  ConvergenceCurve curve;
  curve.label = label;
  curve.evaluations = log_grid(last, points);
  std::vector<double> values(ok.size());
  for (long e : curve.evaluations) {
    for (std::size_t i = 0; i < ok.size(); ++i) values[i] = stats::best_at(ok[i]->trace, e);
    curve.q25.push_back(stats::quantile(values, 0.25));
    curve.median.push_back(stats::quantile(values, 0.5));
    curve.q75.push_back(stats::quantile(values, 0.75));
  }
  return curve;
}

void write_convergence_csv(const std::filesystem::path& path,
                           const std::vector<ConvergenceCurve>& curves) {
  std::string out = "label,evaluations,q25,median,q75\n";
  for (const auto& c : curves) {
    const std::string label = csv_field(c.label);
    for (std::size_t i = 0; i < c.evaluations.size(); ++i)
      out += label + "," + std::to_string(c.evaluations[i]) + "," + csv_number(c.q25[i]) + "," +
             csv_number(c.median[i]) + "," + csv_number(c.q75[i]) + "\n";
  }
  write_file_atomic(path, out);
}

}  // namespace hystbench
