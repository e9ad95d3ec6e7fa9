#include "framework/stats/descriptive.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hystbench::stats {

double mean(const std::vector<double>& v) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  double s = 0.0;
  for (double x : v) s += x;
  return s / double(v.size());
}

double sample_std(const std::vector<double>& v) {
  if (v.size() < 2) return 0.0;
  const double m = mean(v);
  double ss = 0.0;
  for (double x : v) ss += (x - m) * (x - m);
  return std::sqrt(ss / double(v.size() - 1));
}

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  const double h = q * double(v.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(h));
  const std::size_t hi = std::min(lo + 1, v.size() - 1);
  const double w = h - double(lo);
  // Exact order statistics and ties return the value itself, so that an
  // infinite neighbour never turns 0 * inf into NaN.
  if (w == 0.0 || v[lo] == v[hi]) return v[lo];
  return v[lo] + w * (v[hi] - v[lo]);
}

double median(const std::vector<double>& v) { return quantile(v, 0.5); }

}  // namespace hystbench::stats
