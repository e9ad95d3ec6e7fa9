// The sample time of a measurement: inferred from the first and last time,
// and checked against every step, so that a missing row cannot pass.
#include "framework/io/measurement_csv_rows.hpp"

#include "framework/core/eigen.hpp"
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <utility>

#include "framework/core/text.hpp"
#include "framework/io/measurement_csv_lines.hpp"

namespace hystbench::measurement_csv {
namespace {

void check_increasing(const Rows& rows, const std::string& file, const std::string& column) {
  for (std::size_t i = 1; i < rows.t.size(); ++i) {
    if (rows.t[i] <= rows.t[i - 1])
      fail({file, rows.line[i], rows.unit}, column,
           "time " + number_text(rows.t[i]) + " is not after the previous row's " +
               number_text(rows.t[i - 1]) + " (" + rows.unit + " " + std::to_string(rows.line[i - 1]) +
               "); time must strictly increase (sort the rows or remove the duplicate)");
  }
}

// A step may differ from the mean step by 1e-6 relative plus whatever
// rounding the times to the digits they were written with explains (9 digits
// allow 5e-7 s at t = 54 s), but never by 1 % of a step, so a missing sample
// is always caught. The worst step is reported: a missing sample shifts the
// mean step, so the first mismatch is rarely the culprit.
void check_even_steps(const Rows& rows, double dt, const std::string& file,
                      const std::string& column) {
  const double rounding = std::pow(10.0, 1 - std::max(rows.time_digits, 1));
  const double eps = 8 * std::numeric_limits<double>::epsilon();
  std::size_t worst = 0;
  double worst_ratio = 1.0;
  for (std::size_t i = 1; i < rows.t.size(); ++i) {
    const double scale = std::max(std::abs(rows.t[i]), std::abs(rows.t[i - 1]));
    const double tolerance = 1e-6 * dt + std::min(1e-2 * dt, (rounding + eps) * scale);
    const double ratio = std::abs(rows.t[i] - rows.t[i - 1] - dt) / tolerance;
    if (ratio > worst_ratio) {
      worst = i;
      worst_ratio = ratio;
    }
  }
  if (worst == 0) return;
  fail({file, rows.line[worst], rows.unit}, column,
       "the time step " + number_text(rows.t[worst] - rows.t[worst - 1]) + " from " +
           rows.unit + " " + std::to_string(rows.line[worst - 1]) + " differs from the sample time " +
           number_text(dt) + " (first to last time over the sample count); samples must be " +
           "evenly spaced. Is a row missing? If the times are rounded, write more digits");
}

}  // namespace

Measurement to_measurement(Rows& rows, const Header& h, const std::string& file) {
  const std::string& column = h.names[h.t];
  if (rows.t.empty())
    fail({file, h.line}, "the file has a header but no data rows; add one row per sample");
  if (rows.t.size() < 2)
    fail({file, rows.line[0], rows.unit}, "only one sample; at least two are needed to infer the sample time");
  check_increasing(rows, file, column);
  const std::size_t n = rows.t.size();
  const double dt = (rows.t.back() - rows.t.front()) / static_cast<double>(n - 1);
  check_even_steps(rows, dt, file, column);

  Measurement m;
  m.t = Eigen::Map<const Eigen::VectorXd>(rows.t.data(), static_cast<Eigen::Index>(n));
  m.u = Eigen::Map<const Eigen::VectorXd>(rows.u.data(), static_cast<Eigen::Index>(n));
  m.y = Eigen::Map<const Eigen::VectorXd>(rows.y.data(), static_cast<Eigen::Index>(n));
  m.segment = std::move(rows.segment);
  m.sample_time = dt;
  m.source = file;
  return m;
}

}  // namespace hystbench::measurement_csv
