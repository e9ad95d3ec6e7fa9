#include "framework/io/segment_runs.hpp"

#include <algorithm>

namespace hystbench {

std::vector<SegmentRun> segment_runs(const std::vector<std::string>& labels, Eigen::Index n) {
  if (labels.empty())
    return n > 0 ? std::vector<SegmentRun>{{"", 0, n}} : std::vector<SegmentRun>{};
  std::vector<SegmentRun> runs;
  for (Eigen::Index i = 0; i < n;) {
    Eigen::Index end = i + 1;
    while (end < n && labels[std::size_t(end)] == labels[std::size_t(i)]) ++end;
    runs.push_back({labels[std::size_t(i)], i, end});
    i = end;
  }
  return runs;
}

std::vector<std::string> distinct_labels(const std::vector<std::string>& labels) {
  std::vector<std::string> out;
  for (const auto& l : labels)
    if (std::find(out.begin(), out.end(), l) == out.end()) out.push_back(l);
  return out;
}

}  // namespace hystbench
