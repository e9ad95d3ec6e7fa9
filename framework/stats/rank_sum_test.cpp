#include "framework/stats/rank_sum_test.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "framework/core/error.hpp"
#include "framework/stats/descriptive.hpp"
#include "framework/stats/distributions.hpp"
#include "framework/stats/rank_sum_exact.hpp"
#include "framework/stats/ranks.hpp"

namespace hystbench::stats {
namespace {

void check_alpha(double alpha) {
  if (!(alpha > 0 && alpha < 1))
    throw InputError("significance level alpha = " + std::to_string(alpha) +
                     ": must lie strictly between 0 and 1");
}

// sum_t (t^3 - t) over the groups of tied values, for the variance of U.
double tie_term(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  double sum = 0.0;
  for (std::size_t first = 0; first < values.size();) {
    std::size_t last = first + 1;
    while (last < values.size() && values[last] == values[first]) ++last;
    const double t = double(last - first);
    sum += t * t * t - t;
    first = last;
  }
  return sum;
}

bool use_exact(RankSumMethod method, std::size_t n1, std::size_t n2) {
  return method == RankSumMethod::Automatic && rank_sum_exact_applies(n1, n2);
}

bool reference_is_better(const std::vector<double>& reference,
                         const std::vector<double>& competitor, const RankSumResult& r) {
  const double mr = median(reference), mc = median(competitor);
  if (mr != mc) return mr < mc;
  // Equal medians: the sample with the lower mean rank has U_1 < mu_U.
  return r.u < 0.5 * double(reference.size()) * double(competitor.size());
}

}  // namespace

RankSumResult rank_sum_test(const std::vector<double>& first, const std::vector<double>& second,
                            RankSumMethod method) {
  if (first.empty() || second.empty()) throw InputError("rank-sum test: a sample is empty");
  std::vector<double> pooled = first;
  pooled.insert(pooled.end(), second.begin(), second.end());
  const double n1 = double(first.size()), n2 = double(second.size()), n = n1 + n2;
  const std::vector<double> ranks = average_ranks(pooled);
  RankSumResult r;
  r.exact = use_exact(method, first.size(), second.size());
  r.u = std::accumulate(ranks.begin(), ranks.begin() + std::ptrdiff_t(first.size()), 0.0) -
        n1 * (n1 + 1.0) / 2.0;
  // A single pooled value (n = 1) cannot happen: both samples are non-empty.
  const double ties = tie_term(pooled) / (n * (n - 1.0));
  const double variance = n1 * n2 / 12.0 * ((n + 1.0) - ties);
  // Rounding can leave a tiny positive variance when every value ties.
  r.all_tied = !(variance > 1e-12 * n1 * n2);
  if (r.all_tied) return r;
  const double d = r.u - n1 * n2 / 2.0;
  const double correction = d > 0 ? 0.5 : (d < 0 ? -0.5 : 0.0);
  r.z = (d - correction) / std::sqrt(variance);
  r.p = r.exact ? rank_sum_exact_p(ranks, first.size()) : normal_two_sided_p(r.z);
  return r;
}

Mark rank_sum_mark(const std::vector<double>& reference, const std::vector<double>& competitor,
                   double alpha) {
  check_alpha(alpha);
  const RankSumResult r = rank_sum_test(reference, competitor);
  if (!(r.p < alpha)) return Mark::Same;
  return reference_is_better(reference, competitor, r) ? Mark::Better : Mark::Worse;
}

HolmResult holm(const std::vector<double>& p_values, double alpha) {
  check_alpha(alpha);
  for (double p : p_values)
    if (!(p >= 0 && p <= 1))
      throw InputError("Holm correction: p-value " + std::to_string(p) + " is not in [0, 1]");
  const std::size_t m = p_values.size();
  std::vector<std::size_t> order(m);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return p_values[a] < p_values[b]; });
  HolmResult h{std::vector<double>(m), std::vector<bool>(m, false)};
  double running_max = 0.0;
  bool still_rejecting = true;
  for (std::size_t i = 0; i < m; ++i) {
    const double p = p_values[order[i]], factor = double(m - i);
    running_max = std::min(1.0, std::max(running_max, factor * p));
    h.adjusted[order[i]] = running_max;
    still_rejecting = still_rejecting && p < alpha / factor;
    h.rejected[order[i]] = still_rejecting;
  }
  return h;
}

}  // namespace hystbench::stats
