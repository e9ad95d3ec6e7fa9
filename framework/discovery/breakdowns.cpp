#include "framework/discovery/breakdowns.hpp"

#include <algorithm>
#include <cmath>

#include "framework/io/segment_runs.hpp"
#include "framework/io/json_number.hpp"

namespace hystbench {
namespace {

using Rows = std::vector<Eigen::Index>;

ErrorMetrics metrics(const BreakdownInput& in, const Rows& rows) {
  return error_metrics(in.y, in.y_model, rows);
}

std::string part_of(const BreakdownInput& in, const Rows& rows) {
  const auto estimation = std::count_if(
      rows.begin(), rows.end(), [&](Eigen::Index i) { return in.estimation[std::size_t(i)]; });
  if (estimation == long(rows.size())) return "estimation";
  return estimation == 0 ? "heldout" : "mixed";
}

// The group's own keys with its metrics (nlohmann::json keeps keys sorted;
// the order is for readers of the code only).
nlohmann::json group(nlohmann::json keys, const ErrorMetrics& m) {
  keys.update(to_json(m));
  return keys;
}

}  // namespace

std::vector<SegmentErrors> by_segment(const BreakdownInput& in) {
  std::vector<SegmentErrors> out;
  for (const auto& label : distinct_labels(in.segment)) {
    Rows rows;
    for (std::size_t i = 0; i < in.segment.size(); ++i)
      if (in.segment[i] == label) rows.push_back(Eigen::Index(i));
    out.push_back({label, part_of(in, rows), metrics(in, rows)});
  }
  return out;
}

std::vector<AmplitudeErrors> by_amplitude(const BreakdownInput& in) {
  std::vector<double> edges;
  const auto bin = amplitude_bins(in.u, edges);
  std::vector<Rows> rows(kAmplitudeBins);
  for (std::size_t i = 0; i < bin.size(); ++i) rows[std::size_t(bin[i])].push_back(Eigen::Index(i));
  std::vector<AmplitudeErrors> out;
  for (int b = 0; b < kAmplitudeBins; ++b)
    out.push_back({b, edges[std::size_t(b)], edges[std::size_t(b) + 1],
                   metrics(in, rows[std::size_t(b)])});
  return out;
}

BranchErrors by_branch(const BreakdownInput& in) {
  Rows loading, unloading, holding;
  const auto branch = branches(in.u);
  for (std::size_t i = 0; i < branch.size(); ++i)
    (branch[i] > 0 ? loading : branch[i] < 0 ? unloading : holding).push_back(Eigen::Index(i));
  return {metrics(in, loading), metrics(in, unloading), metrics(in, holding)};
}

std::vector<TimeErrors> by_time(const BreakdownInput& in) {
  const Eigen::Index n = in.y.size();
  const Eigen::Index windows = std::min<Eigen::Index>(kTimeWindows, n);
  std::vector<TimeErrors> out;
  for (Eigen::Index w = 0; w < windows; ++w) {
    const Eigen::Index begin = w * n / windows, end = (w + 1) * n / windows;
    Rows rows;
    for (Eigen::Index i = begin; i < end; ++i) rows.push_back(i);
    out.push_back({w, in.t[begin], in.t[end - 1], metrics(in, rows)});
  }
  return out;
}

nlohmann::json to_json(const SegmentErrors& g) {
  return group({{"segment", g.segment}, {"part", g.part}}, g.metrics);
}

nlohmann::json to_json(const AmplitudeErrors& g) {
  return group({{"bin", g.bin},
                {"u_low", number_or_null(g.u_low)},
                {"u_high", number_or_null(g.u_high)}},
               g.metrics);
}

nlohmann::json to_json(const BranchErrors& b) {
  return {{"loading", to_json(b.loading)},
          {"unloading", to_json(b.unloading)},
          {"holding", to_json(b.holding)}};
}

nlohmann::json to_json(const TimeErrors& g) {
  return group({{"window", g.window},
                {"t_start", number_or_null(g.t_start)},
                {"t_end", number_or_null(g.t_end)}},
               g.metrics);
}

}  // namespace hystbench
