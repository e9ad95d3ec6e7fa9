// Reading a measurement CSV: the file's text, the header row and the data
// rows, with a message naming file, line and column for every mistake.
#include "framework/io/measurement.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "framework/core/error.hpp"
#include "framework/io/header_names.hpp"
#include "framework/io/measurement_csv_lines.hpp"
#include "framework/io/measurement_csv_rows.hpp"
#include "framework/io/mat_file.hpp"
#include "framework/io/measurement_mat.hpp"

namespace hystbench {
namespace {

namespace fs = std::filesystem;

using measurement_csv::detect_delimiter;
using measurement_csv::fail;
using measurement_csv::Header;
using measurement_csv::LineReader;
using measurement_csv::Location;
using measurement_csv::Rows;
using measurement_csv::split_csv_line;
using measurement_csv::to_measurement;

// Squares of larger values, summed over a record, overflow a double.
constexpr double kLargestValue = 1e150;
// Files saved where the decimal separator is a comma: what they are and how to fix them.
constexpr const char* kCommaSeparatedPoints =
    "a file with commas between fields needs decimal points (1.5, not 1,5); decimal commas "
    "are read in files with ';' or tabs between fields";

std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "'" : ", '") + s + "'";
  return out;
}

std::string read_text(const fs::path& path) {
  const std::string name = path.string();
  std::error_code ec;
  if (!fs::exists(path, ec))
    throw MissingFileError(name + ": file not found; check the path (a relative path starts at the "
                            "current folder)");
  if (fs::is_directory(path, ec))
    throw InputError(name + ": is a folder; give the path of a measurement CSV file");
  std::ifstream in(path, std::ios::binary);
  const auto size = fs::file_size(path, ec);
  if (!in || ec) throw InputError(name + ": cannot open the file; check that it is readable");
  std::string text(size, '\0');
  in.read(text.data(), static_cast<std::streamsize>(size));
  if (in.gcount() != static_cast<std::streamsize>(size))
    throw InputError(name + ": reading the file failed; check that it is readable");
  return text;
}

// "1,5" or "-0,25": digits on both sides of one comma, as written in a
// locale with decimal commas.
bool decimal_comma(std::string_view field) {
  if (!field.empty() && (field[0] == '-' || field[0] == '+')) field.remove_prefix(1);
  const auto comma = field.find(',');
  const auto digits = [](std::string_view s) {
    return !s.empty() &&
           std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
  };
  return comma != std::string_view::npos && digits(field.substr(0, comma)) &&
         digits(field.substr(comma + 1));
}

double parse_number(std::string_view field, const Location& at, const std::string& column) {
  if (field.empty()) fail(at, column, "the value is empty; every row needs a number here");
  std::string_view digits = field;
  // from_chars rejects a leading '+', which spreadsheets sometimes write.
  if (digits.size() > 1 && digits[0] == '+' && digits[1] != '-') digits.remove_prefix(1);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  const std::string quoted = std::string("'").append(field).append("'");
  if (ec == std::errc::result_out_of_range)
    fail(at, column, quoted + " is out of the range of a double; rescale the column (other units)");
  if (ec != std::errc{} || end != digits.data() + digits.size()) {
    if (decimal_comma(field))
      fail(at, column, quoted + " is not a number: it seems to be written with a decimal comma; " +
                           kCommaSeparatedPoints + ". Write the numbers with '.' instead");
    fail(at, column, quoted + " is not a number; fix the value or comment the line out with '#'");
  }
  if (!std::isfinite(value))
    fail(at, column,
         quoted + " is not a finite number (NaN and Inf are not allowed); fix or remove the row");
  if (std::abs(value) > kLargestValue)
    fail(at, column, quoted + " is too large: squared errors of values beyond 1e150 overflow; "
                              "rescale the column (other units)");
  return value;
}

// Significant digits as written ("54.6106667" has 9). Bounds how much the
// writer rounded the value, which the sample-step check must tolerate.
int significant_digits(std::string_view field) {
  int n = 0;
  for (const char c : field) {
    if (c == 'e' || c == 'E') break;
    if (c >= '1' && c <= '9') ++n;
    if (c == '0' && n > 0) ++n;
  }
  return n;
}

std::optional<std::size_t> find_column(const std::vector<std::string>& names,
                                       const std::string& name) {
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) return std::nullopt;
  return static_cast<std::size_t>(it - names.begin());
}

void check_unique(const std::vector<std::string>& names, const Location& at) {
  for (std::size_t i = 0; i < names.size(); ++i) {
    const auto first = find_column(names, names[i]);
    if (*first != i)
      fail(at, names[i], "appears twice in the header (fields " + std::to_string(*first + 1) +
                             " and " + std::to_string(i + 1) + "); rename one of them");
  }
}

// "--columns 't=Zeit [s],u=U [V],y=Weg [um]'" from the file's own first
// three names, so the advice works when pasted.
std::string columns_hint(const std::vector<std::string>& names) {
  if (names.size() < 3) return "--columns t=t_s,u=u_N,y=y_m";
  std::string spec = "t=" + names[0] + ",u=" + names[1] + ",y=" + names[2];
  const bool quote = spec.find_first_of(" []()'\t") != std::string::npos;
  return "--columns " + (quote ? "'" + spec + "'" : spec) + " (with the right names in that order)";
}

// The column named `name`; for a role left at its default name, also the
// one column known by a common name of the role ("Zeit [s]" for t).
std::size_t require_column(const std::vector<std::string>& names, const std::string& name,
                           ColumnRole role, const Location& at) {
  if (const auto index = find_column(names, name)) return *index;
  const char* r = role_name(role);
  if (name == r) {
    const auto named = columns_named_as(names, role);
    if (named.size() == 1) return named.front();
    std::vector<std::string> which;
    for (auto i : named) which.push_back(names[i]);
    if (named.size() > 1)
      fail(at, "columns " + join(which) + " could each hold " + r + "; tell which with " +
                   columns_hint(names));
  }
  fail(at, "the header has no column '" + name + "' (for " + r + ")" +
               (name == r ? ", nor one named " + role_synonyms(role) + " with or without a unit"
                          : std::string()) +
               "; its columns are " + join(names) + ". Tell which columns hold t, u and y with " +
               columns_hint(names));
}

Header read_header(LineReader& reader, std::vector<std::string>& fields, const ColumnMap& map,
                   const std::string& file) {
  const auto line = reader.next();
  if (!line)
    fail({file}, "no header row: the file is empty or holds only blank and '#' lines; it needs "
                 "a header such as t,u,y and one row per sample");
  const Location at{file, reader.line_number()};
  Header h;
  h.delimiter = map.delimiter ? map.delimiter : detect_delimiter(*line);
  split_csv_line(*line, fields, at, h.delimiter);
  // Before the column checks, which would blame the names: the whole header is one name.
  if (fields.size() == 1 && fields[0].find_first_of(";\t") != std::string::npos)
    fail(at, "the header '" + fields[0] + "' is one field with --delimiter " +
                 std::string(delimiter_name(h.delimiter)) +
                 "; it seems to use another delimiter: leave --delimiter out (auto) or give the "
                 "one the file uses (comma, semicolon or tab)");
  check_unique(fields, at);
  h.names = fields;
  h.line = at.line;
  h.t = require_column(h.names, map.t, ColumnRole::t, at);
  h.u = require_column(h.names, map.u, ColumnRole::u, at);
  h.y = require_column(h.names, map.y, ColumnRole::y, at);
  h.segment = find_column(h.names, map.segment);
  return h;
}

// A row split into too many fields without a single decimal point: its
// numbers were most likely written with decimal commas ("0,001,1,5" for
// 0.001, 1.5).
bool split_decimal_commas(const std::vector<std::string>& fields, const Header& h) {
  return h.delimiter == ',' && fields.size() > h.names.size() &&
         std::none_of(fields.begin(), fields.end(),
                      [](const std::string& f) { return f.find('.') != std::string::npos; });
}

// "1,5" read as 1.5 when fields are not separated by commas.
std::string_view number_text(const std::string& field, const Header& h, std::string& buffer) {
  if (h.delimiter == ',' || !decimal_comma(field)) return field;
  buffer = field;
  std::replace(buffer.begin(), buffer.end(), ',', '.');
  return buffer;
}

void read_row(const std::vector<std::string>& fields, const Header& h, const Location& at,
              Rows& rows) {
  if (split_decimal_commas(fields, h))
    fail(at, "the row has " + std::to_string(fields.size()) + " fields but the header (line " +
                 std::to_string(h.line) + ") has " + std::to_string(h.names.size()) +
                 ", and no decimal point: the file seems to use decimal commas; " +
                 kCommaSeparatedPoints + ". Write the numbers with '.' instead");
  if (fields.size() != h.names.size())
    fail(at, "the row has " + std::to_string(fields.size()) + " fields but the header (line " +
                 std::to_string(h.line) + ") has " + std::to_string(h.names.size()) +
                 "; check for a missing or extra " + std::string(delimiter_name(h.delimiter)));
  std::string buffer;
  const auto value = [&](std::size_t i) {
    return parse_number(number_text(fields[i], h, buffer), at, h.names[i]);
  };
  rows.t.push_back(value(h.t));
  rows.u.push_back(value(h.u));
  rows.y.push_back(value(h.y));
  if (h.segment) rows.segment.push_back(fields[*h.segment]);
  rows.line.push_back(at.line);
  rows.time_digits = std::max(rows.time_digits, significant_digits(fields[h.t]));
}

// Time columns in ms, µs, min or h are read in seconds.
double seconds_per(const std::string& unit) {
  if (unit == "ms") return 1e-3;
  if (unit == "µs") return 1e-6;
  if (unit == "ns") return 1e-9;
  if (unit == "min") return 60.0;
  if (unit == "h") return 3600.0;
  return 1.0;
}

}  // namespace

Measurement read_measurement(const std::filesystem::path& path, const ColumnMap& columns) {
  if (is_mat_file(path)) return read_measurement_mat(path, columns);
  return parse_measurement(read_text(path), path.string(), columns);
}

Measurement parse_measurement(std::string_view text, const std::string& file,
                              const ColumnMap& columns) {
  LineReader reader(text);
  std::vector<std::string> fields;
  const Header header = read_header(reader, fields, columns, file);
  Rows rows;
  while (const auto line = reader.next()) {
    const Location at{file, reader.line_number()};
    split_csv_line(*line, fields, at, header.delimiter);
    read_row(fields, header, at, rows);
  }
  const std::string t_unit = split_unit(header.names[header.t]).unit;
  if (const double seconds = seconds_per(t_unit); seconds != 1.0)
    for (double& t : rows.t) t *= seconds;
  Measurement m = to_measurement(rows, header, file);
  m.u_unit = split_unit(header.names[header.u]).unit;
  m.y_unit = split_unit(header.names[header.y]).unit;
  return m;
}

}  // namespace hystbench
