#include "framework/stats/rank_sum_test.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "framework/core/error.hpp"
#include "framework/stats/distributions.hpp"
#include "framework/stats/ranks.hpp"

namespace hystbench::stats {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(RankTests, AverageRanksGiveTiesTheMeanOfTheirPositions) {
  // Sorted: 1 | 3 3 3 | 7 | inf inf -> ranks 1 | 3 3 3 | 5 | 6.5 6.5.
  const std::vector<double> r = average_ranks({3, kInf, 1, 3, 7, kInf, 3});
  const std::vector<double> expected{3, 6.5, 1, 3, 5, 6.5, 3};
  EXPECT_EQ(r, expected);
  EXPECT_THROW(average_ranks({1, kNaN}), InputError);
}

TEST(RankTests, NormalTailsMatchTableValues) {
  EXPECT_NEAR(normal_cdf(1.959963984540054), 0.975, 1e-12);
  EXPECT_NEAR(normal_two_sided_p(-1.959963984540054), 0.05, 1e-12);
  EXPECT_EQ(normal_two_sided_p(0.0), 1.0);
  // Far tail keeps its digits: 2 (1 - Phi(10)) = 1.5239706e-23.
  EXPECT_NEAR(normal_two_sided_p(10.0) / 1.5239706e-23, 1.0, 1e-6);
}

// Worked by hand; R's wilcox.test(a, b, exact = FALSE, correct = TRUE)
// evaluates the same formula and reports W = U_1 = 3.
//   a = 1 2 3 3 5, b = 3 4 6 7 8 9; pooled ranks: 1 2 (3 3 3 -> 4 4 4) 6 7 8 9 10 11
//   W_1 = 1 + 2 + 4 + 4 + 7 = 18, U_1 = 18 - 15 = 3, mu_U = 15
//   ties: one group of 3 -> 24; sigma^2 = 30/12 (12 - 24/110) = 29.4545...
//   z = (3 - 15 + 0.5) / 5.427204 = -2.118955, p = 0.034094
TEST(RankTests, RankSumNormalApproximationWithTiesMatchesHandComputation) {
  const std::vector<double> a{1, 2, 3, 3, 5}, b{3, 4, 6, 7, 8, 9};
  const RankSumResult r = rank_sum_test(a, b, RankSumMethod::Normal);
  EXPECT_FALSE(r.exact);
  EXPECT_DOUBLE_EQ(r.u, 3.0);
  EXPECT_NEAR(r.z, -11.5 / std::sqrt(2.5 * (12.0 - 24.0 / 110.0)), 1e-12);
  EXPECT_NEAR(r.z, -2.118955, 1e-6);
  EXPECT_NEAR(r.p, 0.034094, 1e-6);
  EXPECT_FALSE(r.all_tied);
  // Swapping the samples mirrors U and z and keeps p.
  const RankSumResult s = rank_sum_test(b, a, RankSumMethod::Normal);
  EXPECT_DOUBLE_EQ(s.u, 30.0 - 3.0);
  EXPECT_NEAR(s.z, -r.z, 1e-12);
  EXPECT_NEAR(s.p, r.p, 1e-12);
}

// The same samples, exactly: 5 of the 11 mid-ranks 1 2 4 4 4 6 7 8 9 10 11
// sum to at most W_1 = 18 in 1 (15: 1 2 4 4 4) + 3 (17: 1 2 4 4 6) + 3 (18:
// 1 2 4 4 7) = 7 of the C(11, 5) = 462 ways, so p = 2 * 7/462 = 1/33.
TEST(RankTests, SmallSamplesWithTiesUseTheExactDistributionOverMidRanks) {
  const std::vector<double> a{1, 2, 3, 3, 5}, b{3, 4, 6, 7, 8, 9};
  const RankSumResult r = rank_sum_test(a, b);
  EXPECT_TRUE(r.exact);
  EXPECT_DOUBLE_EQ(r.u, 3.0);
  EXPECT_NEAR(r.p, 1.0 / 33.0, 1e-15);
  EXPECT_NEAR(rank_sum_test(b, a).p, 1.0 / 33.0, 1e-15);
  // Mid-ranks 1.5 1.5 3.5 3.5 6 6 6: the lowest sum 6.5 of three takes both
  // 1.5 and one of the two 3.5, 2 of C(7, 3) = 35 ways: p = 4/35.
  EXPECT_NEAR(rank_sum_test({0, 0, 1}, {1, 2, 2, 2}).p, 4.0 / 35.0, 1e-15);
}

// Complete separation of 5 against 5: one split of C(10, 5) = 252 has the
// lowest rank sum, two-sided p = 2/252 = 0.00794 (the normal approximation
// would say 0.0122).
TEST(RankTests, ExactFiveAgainstFiveCompleteSeparation) {
  const std::vector<double> low{1, 2, 3, 4, 5}, high{6, 7, 8, 9, 10};
  const RankSumResult r = rank_sum_test(low, high);
  EXPECT_TRUE(r.exact);
  EXPECT_DOUBLE_EQ(r.u, 0.0);
  EXPECT_NEAR(r.p, 2.0 / 252.0, 1e-15);
  EXPECT_NEAR(rank_sum_test(high, low).p, 2.0 / 252.0, 1e-15);
}

// n_1 = 3, n_2 = 4: the C(7, 3) = 35 splits give U = 0..12 with frequencies
// 1 1 2 3 4 4 5 4 4 3 2 1 1 (the partitions of U into at most 3 parts of at
// most 4; Mann & Whitney 1947, Table I: P(U <= 0, 1, 2, 3) = .029 .057 .114
// .200). The first sample holds ranks that give U = 0, 1, 2, 3 and 6.
TEST(RankTests, ExactThreeAgainstFourMatchesTheTable) {
  const auto p = [](std::vector<double> first) {
    std::vector<double> second;
    for (double r = 1; r <= 7; ++r)
      if (std::find(first.begin(), first.end(), r) == first.end()) second.push_back(r);
    return rank_sum_test(first, second).p;
  };
  EXPECT_NEAR(p({1, 2, 3}), 2.0 / 35.0, 1e-15);   // U = 0
  EXPECT_NEAR(p({1, 2, 4}), 4.0 / 35.0, 1e-15);   // U = 1
  EXPECT_NEAR(p({1, 2, 5}), 8.0 / 35.0, 1e-15);   // U = 2
  EXPECT_NEAR(p({1, 2, 6}), 14.0 / 35.0, 1e-15);  // U = 3
  EXPECT_NEAR(p({5, 6, 7}), 2.0 / 35.0, 1e-15);   // U = 12, the other tail
  EXPECT_EQ(p({1, 4, 7}), 1.0);                   // U = 6, the centre: 2 * 20/35 capped
}

// Exact up to 10 values per sample, the normal approximation above.
TEST(RankTests, ExactUpToTenPerSampleNormalAbove) {
  std::vector<double> low, high;
  for (int k = 1; k <= 10; ++k) low.push_back(k), high.push_back(10 + k);
  const RankSumResult ten = rank_sum_test(low, high);
  EXPECT_TRUE(ten.exact);
  EXPECT_NEAR(ten.p / (2.0 / 184756.0), 1.0, 1e-12);  // 2 / C(20, 10)
  high.push_back(21);
  const RankSumResult eleven = rank_sum_test(low, high);
  EXPECT_FALSE(eleven.exact);
  EXPECT_EQ(eleven.p, rank_sum_test(low, high, RankSumMethod::Normal).p);
  EXPECT_FALSE(rank_sum_test(high, low).exact);
}

TEST(RankTests, AllEqualSamplesHaveNoEvidenceAndMarkEqual) {
  const std::vector<double> a{2, 2, 2}, b{2, 2, 2, 2};
  const RankSumResult r = rank_sum_test(a, b);
  EXPECT_TRUE(r.all_tied);
  EXPECT_TRUE(r.exact);  // a single possible rank sum: exactly p = 1
  EXPECT_EQ(r.p, 1.0);
  EXPECT_EQ(r.z, 0.0);
  EXPECT_DOUBLE_EQ(r.u, 6.0);  // = mu_U: every rank is 4
  EXPECT_EQ(rank_sum_mark(a, b), Mark::Same);
  // Failed runs (+inf) tie with each other like any value.
  EXPECT_TRUE(rank_sum_test({kInf, kInf}, {kInf}).all_tied);
}

TEST(RankTests, MarkFollowsSignificanceAndTheLowerMedian) {
  const std::vector<double> a{1, 2, 3, 3, 5}, b{3, 4, 6, 7, 8, 9};  // exact p = 1/33
  EXPECT_EQ(rank_sum_mark(a, b, 0.05), Mark::Better);
  EXPECT_EQ(rank_sum_mark(b, a, 0.05), Mark::Worse);
  EXPECT_EQ(rank_sum_mark(a, b, 0.01), Mark::Same);
  EXPECT_EQ(static_cast<char>(Mark::Better), '+');
  EXPECT_EQ(static_cast<char>(Mark::Worse), '-');
  EXPECT_EQ(static_cast<char>(Mark::Same), '=');
}

// Equal medians (5 and 5), so the mean rank decides. By hand:
//   pooled 0 x3 -> rank 2, 5 x8 -> 7.5, 9 x3 -> 13; W_a = 6 + 30 = 36, U = 8,
//   mu = 24.5, ties 24 + 504 + 24 = 552, sigma^2 = 49/12 (15 - 552/182)
//   z = -16 / 6.990378 = -2.288860, normal p = 0.022087.
//   Exact: 7 of the 14 take a 2s, b 7.5s and c 13s (a + b + c = 7) with
//   2a + 7.5b + 13c <= 36 only as a = 3, b = 4: C(8, 4) = 70 of C(14, 7) = 3432
//   ways, p = 140/3432 = 0.040793.
TEST(RankTests, MarkFallsBackToMeanRankWhenMediansAreEqual) {
  const std::vector<double> a{0, 0, 0, 5, 5, 5, 5}, b{5, 5, 5, 5, 9, 9, 9};
  const RankSumResult r = rank_sum_test(a, b);
  EXPECT_DOUBLE_EQ(r.u, 8.0);
  EXPECT_NEAR(r.p, 140.0 / 3432.0, 1e-15);
  EXPECT_NEAR(rank_sum_test(a, b, RankSumMethod::Normal).p, 0.022087, 1e-6);
  EXPECT_EQ(rank_sum_mark(a, b), Mark::Better);
  EXPECT_EQ(rank_sum_mark(b, a), Mark::Worse);
}

TEST(RankTests, RankSumRejectsEmptySamplesAndBadAlpha) {
  EXPECT_THROW(rank_sum_test({}, {1.0}), InputError);
  EXPECT_THROW(rank_sum_test({1.0, kNaN}, {1.0}), InputError);
  EXPECT_THROW(rank_sum_mark({1.0}, {2.0}, 0.0), InputError);
}

// m = 4; sorted p: 0.005 (x4) 0.01 (x1) 0.03 (x3) 0.04 (x2), by hand:
//   4 * 0.005 = 0.02, 3 * 0.01 = 0.03, 2 * 0.03 = 0.06, 1 * 0.04 = 0.04 -> max so far 0.06
//   step-down at 0.05: 0.005 < 0.0125 yes, 0.01 < 0.0167 yes, 0.03 < 0.025 no: stop.
TEST(RankTests, HolmAdjustsStepDownAndStopsAtTheFirstRetainedHypothesis) {
  const HolmResult h = holm({0.01, 0.04, 0.03, 0.005}, 0.05);
  const std::vector<double> adjusted{0.03, 0.06, 0.06, 0.02};
  ASSERT_EQ(h.adjusted.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(h.adjusted[i], adjusted[i], 1e-15) << i;
  // 0.04 alone would pass 0.04 < 0.05, but Holm stops at 0.03.
  EXPECT_EQ(h.rejected, (std::vector<bool>{true, false, false, true}));
}

TEST(RankTests, HolmAdjustedValuesAreMonotoneCappedAndAgreeWithRejections) {
  const std::vector<double> p{0.2, 0.001, 0.6, 0.011, 0.012, 0.5, 0.0125, 0.9};
  const HolmResult h = holm(p, 0.05);
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_GE(h.adjusted[i], p[i]);
    EXPECT_LE(h.adjusted[i], 1.0);
    EXPECT_EQ(h.rejected[i], h.adjusted[i] < 0.05) << i;
    for (std::size_t j = 0; j < p.size(); ++j) {
      if (p[i] < p[j]) {
        EXPECT_LE(h.adjusted[i], h.adjusted[j]) << i << " " << j;
      }
    }
  }
  // 0.5 * 3 = 1.5 is capped at 1, and the larger p-values keep that 1.
  EXPECT_EQ(h.adjusted[5], 1.0);
  EXPECT_EQ(h.adjusted[7], 1.0);
  EXPECT_EQ(h.rejected, (std::vector<bool>{false, true, false, false, false, false, false, false}));
  EXPECT_TRUE(holm({}, 0.05).adjusted.empty());
  EXPECT_THROW(holm({0.5, 1.5}), InputError);
  EXPECT_THROW(holm({kNaN}), InputError);
}

}  // namespace
}  // namespace hystbench::stats
