#include "framework/discovery/startup_transient.hpp"

#include <algorithm>
#include <cmath>

#include "framework/core/text.hpp"
#include "framework/io/json_number.hpp"

namespace hystbench {

StartupTransient find_startup_transient(const Eigen::VectorXd& e, const ExcitationContent& excitation) {
  StartupTransient t;
  const double total = e.squaredNorm();
  if (!(total > 0) || !std::isfinite(total) || excitation.parts.empty()) return t;  // a diverged model has no transient to name
  double first = 0;
  Eigen::Index samples = 0;
  for (const auto& p : excitation.parts) {
    if (!(p.frequency_hz > 0)) continue;
    const auto period = Eigen::Index(std::ceil(1.0 / (p.frequency_hz * excitation.sample_time)));
    const Eigen::Index end = std::min(p.end, p.begin + period);
    first += e.segment(p.begin, end - p.begin).squaredNorm();
    samples += end - p.begin;
    if (t.warmup == 0) t.warmup = end;
  }
  t.error_share = first / total;
  t.sample_share = double(samples) / double(e.size());
  t.dominates = t.error_share >= kTransientErrorShare &&
                t.error_share >= kTransientConcentration * t.sample_share && t.sample_share < 0.5;
  return t;
}

std::string StartupTransient::sentence() const {
  if (!dominates) return "";
  return "A start-up transient dominates the error: the first period of each excited part holds " +
         format_number("%.0f", 100 * error_share) + " % of the squared error in " +
         format_number("%.1f", 100 * sample_share) +
         " % of the samples. A model started at rest does not follow the actuator until its states "
         "have caught up; no effect cures that. Fit with --warmup " + std::to_string(warmup) +
         " (the first excited part's first period), or trim the record; a record that starts "
         "away from rest (a level held before it) is started there by --initial-state held.";
}

nlohmann::json StartupTransient::to_json() const {
  return {{"dominates", dominates},
          {"error_share", number_or_null(error_share)},
          {"sample_share", number_or_null(sample_share)},
          {"warmup", warmup},
          {"sentence", sentence()}};
}

}  // namespace hystbench
