#pragma once
// The segment markers of the fit_LABEL_time figure, apart from the figure
// because placing the names so that none overlap is a job of its own.
#include "framework/core/eigen.hpp"
#include <string>
#include <vector>

namespace hystbench::figure_script {

// A dashed line where the segment changes and its name in a strip kept
// free above the data, so a misfit can be traced to its excitation. Names
// that would run into each other alternate between two rows.
std::string segment_markers(const std::vector<std::string>& segments, const Eigen::VectorXd& t);

}  // namespace hystbench::figure_script
