#pragma once
// The figures of `hystbench svr`: per test signal, the hysteresis loop
// (measured, SVR and grey-box displacement against the input, over the
// scored part), and the relative error of each model by test signal.
#include <filesystem>
#include <vector>

#include "framework/svr/svr_run.hpp"

namespace hystbench {

// Writes the data files and gnuplot scripts; returns the scripts.
std::vector<std::filesystem::path> write_svr_figures(const std::filesystem::path& dir, const SvrExperiment& x,
                                                     const SvrResults& r);

}  // namespace hystbench
