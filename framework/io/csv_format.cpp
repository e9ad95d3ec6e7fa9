#include "framework/io/csv_format.hpp"

#include <charconv>
#include <cmath>

namespace hystbench {

namespace {

std::string number_cell(double x, int digits) {
  if (std::isnan(x)) return "";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buf[32];
  // to_chars with a precision formats as printf's %.<digits>g does.
  const auto end = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::general, digits).ptr;
  return std::string(buf, end);
}

}  // namespace

std::string csv_number(double x) { return number_cell(x, 17); }

std::string figure_number(double x) { return number_cell(x, 6); }

std::string csv_field(const std::string& s) {
  return s.find_first_of(",\"\n\r") == std::string::npos ? s : csv_quoted(s);
}

std::string csv_quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

}  // namespace hystbench
