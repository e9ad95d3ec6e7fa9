#pragma once
// Contiguous stretches of equal segment labels. A label that comes back
// later starts a new run, so a run is always one unbroken excitation.
#include "framework/core/eigen.hpp"
#include <string>
#include <vector>

namespace hystbench {

struct SegmentRun {
  std::string label;
  Eigen::Index begin = 0, end = 0;  // samples [begin, end)
  Eigen::Index size() const { return end - begin; }
};

// One run per stretch in time order; one unnamed run over all n samples
// when there are no labels.
std::vector<SegmentRun> segment_runs(const std::vector<std::string>& labels, Eigen::Index n);

// Distinct labels in order of first appearance.
std::vector<std::string> distinct_labels(const std::vector<std::string>& labels);

}  // namespace hystbench
