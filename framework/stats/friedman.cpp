#include "framework/stats/friedman.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "framework/core/error.hpp"
#include "framework/stats/distributions.hpp"
#include "framework/stats/rank_sum_test.hpp"
#include "framework/stats/ranks.hpp"

namespace hystbench::stats {
namespace {

// Demsar (2006), table 5(a), k = 2..10; the same values as
// docs/algorithms.md#friedman-test.
constexpr std::array<double, 9> kNemenyiQ05{1.960, 2.343, 2.569, 2.728, 2.850,
                                            2.949, 3.031, 3.102, 3.164};

void check_shape(const std::vector<std::vector<double>>& values) {
  if (values.size() < 2)
    throw InputError("Friedman test: needs at least 2 blocks (problems), got " +
                     std::to_string(values.size()));
  const std::size_t k = values.front().size();
  if (k < 2)
    throw InputError("Friedman test: needs at least 2 algorithms, got " + std::to_string(k));
  for (std::size_t i = 0; i < values.size(); ++i)
    if (values[i].size() != k)
      throw InputError("Friedman test: block " + std::to_string(i) + " has " +
                       std::to_string(values[i].size()) + " values, block 0 has " +
                       std::to_string(k));
}

std::vector<double> mean_ranks(const std::vector<std::vector<double>>& values) {
  std::vector<double> sum(values.front().size(), 0.0);
  for (const auto& block : values) {
    const std::vector<double> r = average_ranks(block);
    for (std::size_t j = 0; j < r.size(); ++j) sum[j] += r[j];
  }
  for (double& s : sum) s /= double(values.size());
  return sum;
}

double chi2_statistic(const std::vector<double>& ranks, double n) {
  const double k = double(ranks.size());
  // sum_j (R_j - (k + 1)/2)^2 equals sum_j R_j^2 - k (k + 1)^2 / 4 (the
  // R_j average (k + 1)/2) without cancelling two nearly equal sums.
  double sum = 0.0;
  for (double r : ranks) sum += (r - (k + 1.0) / 2.0) * (r - (k + 1.0) / 2.0);
  return 12.0 * n / (k * (k + 1.0)) * sum;
}

double iman_davenport(double chi2, double n, double k) {
  const double denominator = n * (k - 1.0) - chi2;
  // chi2_F <= N (k - 1); equality (up to rounding) means perfect agreement.
  if (denominator <= 1e-12 * n * (k - 1.0)) return std::numeric_limits<double>::infinity();
  return (n - 1.0) * chi2 / denominator;
}

double rank_standard_error(int k, int n) { return std::sqrt(k * (k + 1.0) / (6.0 * n)); }

ControlComparison versus_control(const FriedmanResult& result, int j, int control) {
  const auto& ranks = result.average_ranks;
  ControlComparison c;
  c.algorithm = j;
  c.z = (ranks[std::size_t(j)] - ranks[std::size_t(control)]) /
        rank_standard_error(int(ranks.size()), result.blocks);
  c.p = normal_two_sided_p(c.z);
  return c;
}

}  // namespace

FriedmanResult friedman_test(const std::vector<std::vector<double>>& values) {
  check_shape(values);
  FriedmanResult r;
  r.blocks = int(values.size());
  r.algorithms = int(values.front().size());
  r.average_ranks = mean_ranks(values);
  const double n = r.blocks, k = r.algorithms;
  r.chi2 = chi2_statistic(r.average_ranks, n);
  r.chi2_p = chi_squared_survival(r.chi2, k - 1.0);
  r.f = iman_davenport(r.chi2, n, k);
  r.f_p = f_survival(r.f, k - 1.0, (k - 1.0) * (n - 1.0));
  return r;
}

double nemenyi_q05(int algorithms) {
  if (algorithms < 2 || algorithms > int(kNemenyiQ05.size()) + 1)
    throw InputError("Nemenyi test: q_0.05 is tabulated for 2 to 10 algorithms, got " +
                     std::to_string(algorithms));
  return kNemenyiQ05[std::size_t(algorithms - 2)];
}

double nemenyi_critical_difference(int algorithms, int blocks) {
  if (blocks < 1)
    throw InputError("Nemenyi test: needs at least 1 block, got " + std::to_string(blocks));
  return nemenyi_q05(algorithms) * rank_standard_error(algorithms, blocks);
}

std::vector<ControlComparison> compare_with_control(const FriedmanResult& result, int control,
                                                    double alpha) {
  const int k = int(result.average_ranks.size());
  if (control < 0 || control >= k)
    throw InputError("Friedman control: index " + std::to_string(control) +
                     " is not one of the " + std::to_string(k) + " algorithms");
  if (result.blocks < 1) throw InputError("Friedman control: the result has no blocks");
  std::vector<ControlComparison> out;
  std::vector<double> p;
  for (int j = 0; j < k; ++j) {
    if (j == control) continue;
    out.push_back(versus_control(result, j, control));
    p.push_back(out.back().p);
  }
  const HolmResult h = holm(p, alpha);
  for (std::size_t i = 0; i < out.size(); ++i) {
    out[i].p_holm = h.adjusted[i];
    out[i].rejected = h.rejected[i];
  }
  return out;
}

}  // namespace hystbench::stats
