#include "framework/discovery/excitation_frequency.hpp"

#include <cmath>
#include <limits>

#include "framework/io/segment_runs.hpp"

namespace hystbench {

double crossing_frequency(const Eigen::VectorXd& u, Eigen::Index begin, Eigen::Index end,
                          double sample_time) {
  if (end - begin < 3 || !(sample_time > 0)) return std::numeric_limits<double>::quiet_NaN();
  const double mean = u.segment(begin, end - begin).mean();
  long crossings = 0;
  for (Eigen::Index k = begin + 1; k < end; ++k)
    if ((u[k - 1] - mean < 0) != (u[k] - mean < 0)) ++crossings;
  if (crossings < 2) return std::numeric_limits<double>::quiet_NaN();
  return double(crossings) / (2.0 * double(end - begin) * sample_time);
}

double lowest_excitation_frequency(const Eigen::VectorXd& u,
                                   const std::vector<std::string>& segment, double sample_time) {
  double low = std::numeric_limits<double>::quiet_NaN();
  for (const auto& r : segment_runs(segment, u.size())) {
    const double f = crossing_frequency(u, r.begin, r.end, sample_time);
    if (std::isfinite(f) && !(f >= low)) low = f;
  }
  return std::isfinite(low) ? low : 1.0 / (double(u.size()) * sample_time);
}

}  // namespace hystbench
