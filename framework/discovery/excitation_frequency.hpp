#pragma once
// How slowly the record is driven: the time scale below which a residual
// counts as slow (creep, drift), taken from the input's zero crossings.
#include "framework/core/eigen.hpp"
#include <string>
#include <vector>

namespace hystbench {

// Dominant frequency of u over [begin, end) from the zero crossings of
// u − mean (Hz); NaN when it crosses fewer than twice.
double crossing_frequency(const Eigen::VectorXd& u, Eigen::Index begin, Eigen::Index end,
                          double sample_time);

// Lowest crossing frequency over the segment runs (segment_runs.hpp); 1 / the
// record's duration when no run oscillates.
double lowest_excitation_frequency(const Eigen::VectorXd& u,
                                   const std::vector<std::string>& segment, double sample_time);

}  // namespace hystbench
