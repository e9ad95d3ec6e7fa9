#pragma once
// Descriptive statistics, computed stably (two passes, no running sums of squares).
#include <vector>

namespace hystbench::stats {

double mean(const std::vector<double>& v);
// Sample standard deviation, dividing by n - 1 (0 for fewer than 2 values).
double sample_std(const std::vector<double>& v);
// Quantile with linear interpolation between order statistics (R type 7);
// q in [0, 1]. `v` need not be sorted.
double quantile(std::vector<double> v, double q);
double median(const std::vector<double>& v);

}  // namespace hystbench::stats
