// libFuzzer target for the measurement CSV reader (framework/io/measurement.*)
// and csv_number (framework/io/csv_format.*). Bad input must end in
// an InputError; any other exception, a crash or a sanitizer report is a
// finding. The u and y that were read are written back with csv_number and
// read again: they must come back unchanged. (Times are written back as
// 0, 1, 2, ...: the reader's tolerance for uneven steps follows the digits
// the times were written with, so they need not survive 17 digits.)
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "framework/core/error.hpp"
#include "framework/io/csv_format.hpp"
#include "framework/io/measurement.hpp"

namespace {

void require(bool ok) {
  if (!ok) std::abort();
}

std::string write_back(const hystbench::Measurement& m) {
  std::string text = "t,u,y\n";
  for (Eigen::Index i = 0; i < m.size(); ++i)
    text += std::to_string(i) + "," + hystbench::csv_number(m.u[i]) + "," +
            hystbench::csv_number(m.y[i]) + "\n";
  return text;
}

void check_read(const hystbench::Measurement& m) {
  require(m.size() >= 2 && m.u.size() == m.size() && m.y.size() == m.size());
  require(m.segment.empty() || m.segment.size() == static_cast<std::size_t>(m.size()));
  for (Eigen::Index i = 1; i < m.size(); ++i) require(m.t[i] > m.t[i - 1]);
  require(m.sample_time > 0 && m.sample_time == (m.t[m.size() - 1] - m.t[0]) / double(m.size() - 1));
  const hystbench::Measurement again = hystbench::parse_measurement(write_back(m), "again");
  require(again.u == m.u && again.y == m.y);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  hystbench::Measurement m;
  try {
    m = hystbench::parse_measurement(text, "fuzz.csv");
  } catch (const hystbench::InputError&) {
    return 0;
  }
  check_read(m);
  return 0;
}
