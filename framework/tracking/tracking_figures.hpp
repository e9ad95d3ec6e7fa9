#pragma once
// The figures of `hystbench track`: per reference, the reference, the
// output and the error over the scored periods for one controller (as seed
// 002's Fig. 11), and the Bode plot of the full against the reduced H∞
// controller (as its Fig. 9).
#include <filesystem>
#include <vector>

#include "framework/tracking/tracking_run.hpp"

namespace hystbench {

// Writes the data files and gnuplot scripts; returns the scripts.
std::vector<std::filesystem::path> write_tracking_figures(const std::filesystem::path& dir,
                                                          const TrackingExperiment& x, const TrackingResults& r);

}  // namespace hystbench
