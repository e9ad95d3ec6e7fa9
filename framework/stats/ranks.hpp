#pragma once
// Ranks shared by the rank-based tests (rank-sum, Friedman).
#include <vector>

namespace hystbench::stats {

// 1-based ranks in ascending order of `values`; a group of tied values gets
// the average of the ranks it spans, so that the rank sum stays n (n + 1) / 2
// whatever the ties. Throws InputError for a NaN (it has no place in an
// order). +inf is an ordinary, largest value: failed runs rank last.
std::vector<double> average_ranks(const std::vector<double>& values);

}  // namespace hystbench::stats
