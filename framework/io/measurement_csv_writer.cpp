// Writing a measurement CSV that the reader reads back exactly: every
// number to 17 digits, and labels quoted where the reader would change them.
#include "framework/io/measurement.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "framework/core/error.hpp"
#include "framework/io/atomic_file.hpp"
#include "framework/io/csv_format.hpp"
#include "framework/io/mat_file.hpp"
#include "framework/io/measurement_csv_lines.hpp"
#include "framework/io/measurement_mat.hpp"

namespace hystbench {
namespace {

using measurement_csv::trim;

// Quotes a label only when the reader would otherwise split or trim it.
std::string segment_cell(const std::string& s, const std::string& file) {
  if (s.find_first_of("\r\n") != std::string::npos)
    throw InputError(file + ": segment label '" + s +
                     "' contains a line break; labels must be one line");
  const bool plain = s.find_first_of(",\"") == std::string::npos && trim(s).size() == s.size();
  return plain ? s : csv_quoted(s);
}

std::string comment_lines(const std::vector<std::string>& comments) {
  std::string out;
  for (const auto& comment : comments) {
    std::string_view rest = comment;
    for (;;) {  // a multi-line comment becomes several '#' lines
      const std::size_t end = std::min(rest.find('\n'), rest.size());
      std::string_view line = rest.substr(0, end);
      if (line.ends_with('\r')) line.remove_suffix(1);
      out.append("# ").append(line).append("\n");
      if (end == rest.size()) break;
      rest.remove_prefix(end + 1);
    }
  }
  return out;
}

void check_writable(const Measurement& m, const std::string& file) {
  const Eigen::Index n = m.t.size();
  if (m.u.size() != n || m.y.size() != n ||
      (!m.segment.empty() && m.segment.size() != static_cast<std::size_t>(n)))
    throw std::invalid_argument("write_measurement(" + file +
                                "): t, u, y and segment differ in length");
  for (Eigen::Index i = 0; i < n; ++i) {
    if (!std::isfinite(m.t[i]) || !std::isfinite(m.u[i]) || !std::isfinite(m.y[i]))
      throw InputError(file + ": sample " + std::to_string(i) +
                       " is not finite (NaN or Inf); a measurement file holds finite numbers only");
  }
}

}  // namespace

void write_measurement(const std::filesystem::path& path, const Measurement& m,
                       const std::vector<std::string>& comments) {
  const std::string file = path.string();
  check_writable(m, file);
  if (has_mat_extension(path)) return write_measurement_mat(path, m);
  const bool segments = !m.segment.empty();
  std::string out = comment_lines(comments);
  out += segments ? "t,u,y,segment\n" : "t,u,y\n";
  for (Eigen::Index i = 0; i < m.t.size(); ++i) {
    out += csv_number(m.t[i]);
    out += ',';
    out += csv_number(m.u[i]);
    out += ',';
    out += csv_number(m.y[i]);
    if (segments) out += ',' + segment_cell(m.segment[static_cast<std::size_t>(i)], file);
    out += '\n';
  }
  write_file_atomic(path, out);
}

}  // namespace hystbench
