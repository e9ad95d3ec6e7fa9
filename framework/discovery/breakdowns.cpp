#include "framework/discovery/breakdowns.hpp"

#include <algorithm>
#include <cmath>

#include "framework/discovery/error_metrics.hpp"
#include "framework/discovery/segment_runs.hpp"

namespace hystbench {
namespace {

using Rows = std::vector<Eigen::Index>;

nlohmann::json metrics(const BreakdownInput& in, const Rows& rows) {
  return to_json(error_metrics(in.y, in.y_model, rows));
}

std::string part_of(const BreakdownInput& in, const Rows& rows) {
  const auto estimation = std::count_if(
      rows.begin(), rows.end(), [&](Eigen::Index i) { return in.estimation[std::size_t(i)]; });
  if (estimation == long(rows.size())) return "estimation";
  return estimation == 0 ? "heldout" : "mixed";
}

// Metrics first, then the group's own keys in front (nlohmann::json keeps
// keys sorted; the order is for readers of the code only).
nlohmann::json group(const BreakdownInput& in, const Rows& rows, nlohmann::json keys) {
  keys.update(metrics(in, rows));
  return keys;
}

}  // namespace

nlohmann::json by_segment(const BreakdownInput& in) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& label : distinct_labels(in.segment)) {
    Rows rows;
    for (std::size_t i = 0; i < in.segment.size(); ++i)
      if (in.segment[i] == label) rows.push_back(Eigen::Index(i));
    out.push_back(group(in, rows, {{"segment", label}, {"part", part_of(in, rows)}}));
  }
  return out;
}

nlohmann::json by_amplitude(const BreakdownInput& in) {
  std::vector<double> edges;
  const auto bin = amplitude_bins(in.u, edges);
  std::vector<Rows> rows(kAmplitudeBins);
  for (std::size_t i = 0; i < bin.size(); ++i) rows[std::size_t(bin[i])].push_back(Eigen::Index(i));
  nlohmann::json out = nlohmann::json::array();
  for (int b = 0; b < kAmplitudeBins; ++b)
    out.push_back(group(in, rows[std::size_t(b)],
                        {{"bin", b},
                         {"u_low", finite_or_null(edges[std::size_t(b)])},
                         {"u_high", finite_or_null(edges[std::size_t(b) + 1])}}));
  return out;
}

nlohmann::json by_branch(const BreakdownInput& in) {
  Rows loading, unloading, holding;
  const auto branch = branches(in.u);
  for (std::size_t i = 0; i < branch.size(); ++i)
    (branch[i] > 0 ? loading : branch[i] < 0 ? unloading : holding).push_back(Eigen::Index(i));
  return {{"loading", metrics(in, loading)},
          {"unloading", metrics(in, unloading)},
          {"holding", metrics(in, holding)}};
}

nlohmann::json by_time(const BreakdownInput& in) {
  const Eigen::Index n = in.y.size();
  const Eigen::Index windows = std::min<Eigen::Index>(kTimeWindows, n);
  nlohmann::json out = nlohmann::json::array();
  for (Eigen::Index w = 0; w < windows; ++w) {
    const Eigen::Index begin = w * n / windows, end = (w + 1) * n / windows;
    Rows rows;
    for (Eigen::Index i = begin; i < end; ++i) rows.push_back(i);
    out.push_back(group(in, rows,
                        {{"window", w},
                         {"t_start", finite_or_null(in.t[begin])},
                         {"t_end", finite_or_null(in.t[end - 1])}}));
  }
  return out;
}

}  // namespace hystbench
