#include "framework/svr/svr_record.hpp"

#include "framework/core/error.hpp"
#include "framework/io/segment_runs.hpp"
#include "framework/io/data_path.hpp"

namespace hystbench {

Measurement slice(const Measurement& m, Eigen::Index begin, Eigen::Index end) {
  Measurement out;
  out.t = m.t.segment(begin, end - begin);
  out.u = m.u.segment(begin, end - begin);
  out.y = m.y.segment(begin, end - begin);
  if (!m.segment.empty()) out.segment.assign(m.segment.begin() + begin, m.segment.begin() + end);
  out.sample_time = m.sample_time;
  out.source = m.source;
  return out;
}

SvrRecord read_svr_record(const std::string& file, const std::string& segment, const ColumnMap& columns,
                          const std::filesystem::path& base_dir, const std::string& where) {
  const auto path = resolve_data_path(file, base_dir, where + ".data");
  Measurement m = read_measurement(path, columns);
  const std::string name = path.filename().string();
  if (segment.empty()) return {name, std::move(m)};
  std::vector<SegmentRun> found;
  for (const auto& run : segment_runs(m.segment, m.size()))
    if (run.label == segment) found.push_back(run);
  if (found.empty()) {
    std::string present;
    for (const auto& label : distinct_labels(m.segment)) present += (present.empty() ? "\"" : ", \"") + label + "\"";
    throw InputError(where + ".segment: \"" + segment + "\" is not a segment of " + name +
                     (present.empty() ? " (it has no segment column)" : "; its segments: " + present));
  }
  if (found.size() > 1)
    throw InputError(where + ".segment: \"" + segment + "\" comes back " + std::to_string(found.size()) +
                     " times in " + name + "; give each stretch its own label");
  return {name + " [" + segment + "]", slice(m, found[0].begin, found[0].end)};
}

}  // namespace hystbench
