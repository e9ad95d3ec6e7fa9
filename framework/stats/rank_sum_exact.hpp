#pragma once
// Exact two-sided p-value of the rank-sum statistic for small samples, from
// the permutation distribution: under H0 every split of the n pooled values
// into the two samples is equally likely, so P(W_1 = w) is the number of
// n_1-subsets of the pooled ranks that sum to w over C(n, n_1).
#include <cstddef>
#include <vector>

namespace hystbench::stats {

// Both samples at most this size: the exact test is used. Beyond it the
// normal approximation with continuity correction is close at the usual
// levels, and the count table grows as n_1 n^2.
inline constexpr std::size_t kExactRankSumMaxSize = 10;

bool rank_sum_exact_applies(std::size_t n1, std::size_t n2);

// `ranks`: the average ranks of the pooled sample (average_ranks), the first
// n1 belonging to the first sample. Ties keep their mid-ranks, which gives
// the distribution conditional on the observed tie pattern: still exact.
// Two-sided p = min(1, 2 min(P(W_1 <= w), P(W_1 >= w))), as R's
// wilcox.test(exact = TRUE) gives without ties (R refuses the exact test
// with ties); with ties the distribution need not be symmetric, hence the
// smaller tail rather than |W_1 - mu| >= |w - mu|.
double rank_sum_exact_p(const std::vector<double>& ranks, std::size_t n1);

}  // namespace hystbench::stats
