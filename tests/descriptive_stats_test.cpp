#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "framework/stats/descriptive.hpp"

namespace hystbench::stats {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(DescriptiveStats, QuantilesInterpolateBetweenOrderStatistics) {
  const std::vector<double> v{4, 1, 3, 2};  // sorted 1 2 3 4
  EXPECT_DOUBLE_EQ(median(v), 2.5);
  EXPECT_DOUBLE_EQ(quantile(v, 0.25), 1.75);  // h = 0.75
  EXPECT_DOUBLE_EQ(quantile(v, 1.0), 4.0);
}

TEST(DescriptiveStats, InfiniteValuesNeverGiveNan) {
  const std::vector<double> v{1, 2, kInf};
  EXPECT_EQ(median(v), 2.0);  // exact order statistic beside an infinity
  EXPECT_EQ(quantile(v, 0.75), kInf);
  EXPECT_EQ(quantile({kInf, kInf}, 0.5), kInf);
}

TEST(DescriptiveStats, SampleStdDividesByNMinusOneAndIsStableForLargeOffsets) {
  EXPECT_DOUBLE_EQ(sample_std({2, 4, 4, 4, 5, 5, 7, 9}), std::sqrt(32.0 / 7.0));
  // A one-pass sum of squares loses every digit here; two passes do not.
  EXPECT_NEAR(sample_std({1e9 + 4, 1e9 + 7, 1e9 + 13, 1e9 + 16}), std::sqrt(30.0), 1e-6);
  EXPECT_EQ(sample_std({3.0}), 0.0);
}

}  // namespace
}  // namespace hystbench::stats
