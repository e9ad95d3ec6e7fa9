#include "framework/stats/rank_sum_exact.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace hystbench::stats {
namespace {

// Mid-ranks are whole or half numbers: doubled, they index the count table.
std::vector<std::size_t> doubled(const std::vector<double>& ranks) {
  std::vector<std::size_t> out;
  for (double r : ranks) out.push_back(std::size_t(std::lround(2.0 * r)));
  return out;
}

// count[k][s]: the number of k-subsets of the ranks seen so far whose
// doubled sum is s. Adding a rank r, a subset either leaves it out or takes
// it: count'[k][s] = count[k][s] + count[k - 1][s - r]. This is the counting
// recursion of Mann & Whitney (Ann. Math. Statist. 18(1):50-60, 1947) for
// the frequencies of U, taken one pooled observation at a time so that it
// also runs over mid-ranks. At most C(20, 10) = 184756 subsets: doubles
// count them exactly.
std::vector<double> subset_sum_counts(const std::vector<std::size_t>& ranks2, std::size_t n1) {
  const std::size_t total = std::accumulate(ranks2.begin(), ranks2.end(), std::size_t{0});
  std::vector<std::vector<double>> count(n1 + 1, std::vector<double>(total + 1, 0.0));
  count[0][0] = 1.0;
  std::size_t seen = 0;
  for (std::size_t r : ranks2) {
    seen += r;
    // Downwards in k, so that each rank is taken at most once.
    for (std::size_t k = n1; k >= 1; --k)
      for (std::size_t s = seen; s >= r; --s) count[k][s] += count[k - 1][s - r];
  }
  return count[n1];
}

}  // namespace

bool rank_sum_exact_applies(std::size_t n1, std::size_t n2) {
  return n1 <= kExactRankSumMaxSize && n2 <= kExactRankSumMaxSize;
}

double rank_sum_exact_p(const std::vector<double>& ranks, std::size_t n1) {
  const auto ranks2 = doubled(ranks);
  const std::size_t w2 =
      std::accumulate(ranks2.begin(), ranks2.begin() + std::ptrdiff_t(n1), std::size_t{0});
  const std::vector<double> count = subset_sum_counts(ranks2, n1);
  double below = 0.0, above = 0.0, all = 0.0;
  for (std::size_t s = 0; s < count.size(); ++s) {
    all += count[s];
    if (s <= w2) below += count[s];
    if (s >= w2) above += count[s];
  }
  return std::min(1.0, 2.0 * std::min(below, above) / all);
}

}  // namespace hystbench::stats
