// Segment markers of the fit time figure: the stretches of each segment in
// time order, and their names in one row or, where they would collide, two.
#include "framework/report/fit_segment_markers.hpp"

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

#include "framework/io/segment_runs.hpp"
#include "framework/report/gnuplot_script.hpp"

namespace hystbench::figure_script {
namespace {

struct TimeSegment {
  std::string name;
  double begin, end;
};

// Contiguous stretches in time order: a name that comes back is a new one.
// A stretch ends where the next begins, the last at the last sample.
std::vector<TimeSegment> time_segments(const std::vector<std::string>& segments,
                                       const Eigen::VectorXd& t) {
  std::vector<TimeSegment> out;
  if (segments.empty()) return out;
  for (const SegmentRun& run : segment_runs(segments, Eigen::Index(segments.size())))
    out.push_back({run.label, t[run.begin], t[std::min(run.end, t.size() - 1)]});
  return out;
}

// Whether neighbouring names, centred on their stretches, would overlap in
// the PDF, the most crowded output (10 pt letters up to 7 pt wide across
// about 340 pt of plot).
bool names_collide(const std::vector<TimeSegment>& segs) {
  const double per_char = 7.0 / 340.0 * (segs.back().end - segs.front().begin);
  for (std::size_t k = 1; k < segs.size(); ++k) {
    const double distance = (segs[k].end - segs[k - 1].begin) / 2;  // between the centres
    const auto letters = double(segs[k].name.size() + segs[k - 1].name.size()) / 2 + 1;
    const double needed = letters * per_char;
    if (distance < needed) return true;
  }
  return false;
}

}  // namespace

std::string segment_markers(const std::vector<std::string>& segments, const Eigen::VectorXd& t) {
  const auto segs = time_segments(segments, t);
  if (segs.empty()) return "  set offsets 0, 0, graph 0.05, graph 0.05\n";
  const bool two_rows = names_collide(segs);
  std::string out = std::string("  set offsets 0, 0, graph ") + (two_rows ? "0.45" : "0.22") +
                    ", graph 0.05\n";
  for (std::size_t k = 0; k < segs.size(); ++k) {
    const std::string begin = gnuplot::number(segs[k].begin);
    if (k > 0)
      out += "  set arrow from " + begin + ", graph 0 to " + begin +
             ", graph 1 nohead lc rgb \"#a0a0a0\" dt 2 back\n";
    out += "  set label " + gnuplot::quoted(segs[k].name) + " at " +
           gnuplot::number((segs[k].begin + segs[k].end) / 2) + ", graph " +
           (two_rows && k % 2 ? "0.81" : "0.92") + " center noenhanced\n";
  }
  return out;
}

}  // namespace hystbench::figure_script
