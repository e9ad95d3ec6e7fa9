#include "framework/io/measurement.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string_view>

#include "framework/core/error.hpp"
#include "framework/io/atomic_file.hpp"

namespace hystbench {
namespace {

namespace fs = std::filesystem;

constexpr const char* kRoleList = "t, u, y, segment";
// Squares of larger values, summed over a record, overflow a double.
constexpr double kLargestValue = 1e150;
constexpr const char* kColumnsHint = "--columns t=t_s,u=u_N,y=y_m";
// Files saved where the decimal separator is a comma: what they are and how to fix them.
constexpr const char* kCommaSeparatedPoints =
    "hystbench reads comma-separated files with decimal points (1.5, not 1,5)";

// Where a problem is. Messages are only built when one occurs, so reading a
// long file costs nothing for it.
struct Location {
  const std::string& file;
  std::size_t line = 0;  // 1-based physical line; 0 means the whole file
};

[[noreturn]] void fail(const Location& at, const std::string& what) {
  std::string where = at.file;
  if (at.line > 0) where += ", line " + std::to_string(at.line);
  throw InputError(where + ": " + what);
}

[[noreturn]] void fail(const Location& at, const std::string& column, const std::string& what) {
  fail(at, "column '" + column + "': " + what);
}

// Shortest text that reads back as the same double.
std::string number_text(double v) {
  char buf[32];
  const auto result = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, result.ptr);
}

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "'" : ", '") + s + "'";
  return out;
}

std::string* role_field(ColumnMap& map, std::string_view role) {
  if (role == "t") return &map.t;
  if (role == "u") return &map.u;
  if (role == "y") return &map.y;
  if (role == "segment") return &map.segment;
  return nullptr;
}

// ---- reading -------------------------------------------------------------

std::string read_text(const fs::path& path) {
  const std::string name = path.string();
  std::error_code ec;
  if (!fs::exists(path, ec))
    throw InputError(name + ": file not found; check the path (a relative path starts at the "
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

// Hands out the lines that carry content: blank lines and '#' comments are
// skipped, but still counted so that messages point at the right line.
class LineReader {
 public:
  explicit LineReader(std::string_view text) : text_(text) {
    if (text_.starts_with("\xEF\xBB\xBF")) text_.remove_prefix(3);  // UTF-8 BOM
  }

  std::optional<std::string_view> next() {
    while (pos_ < text_.size()) {
      const std::size_t end = std::min(text_.find('\n', pos_), text_.size());
      std::string_view line = text_.substr(pos_, end - pos_);
      pos_ = end + 1;
      ++line_;
      if (line.ends_with('\r')) line.remove_suffix(1);
      const std::string_view body = trim(line);
      if (!body.empty() && body.front() != '#') return line;
    }
    return std::nullopt;
  }

  std::size_t line_number() const { return line_; }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_ = 0;
};

// Reads the quoted field that starts at line[pos]; "" stands for one quote.
// Leaves pos just after the closing quote.
void read_quoted(std::string_view line, std::size_t& pos, std::string& out, const Location& at) {
  out.clear();
  for (++pos; pos < line.size(); ++pos) {
    if (line[pos] != '"') {
      out += line[pos];
    } else if (pos + 1 < line.size() && line[pos + 1] == '"') {
      out += '"';
      ++pos;
    } else {
      ++pos;
      return;
    }
  }
  fail(at, "a quoted field has no closing '\"'; close the quote (a field cannot span lines)");
}

// Splits one CSV line into fields without quotes and surrounding blanks.
// `fields` is reused from line to line so a long file does not allocate per row.
void split_csv_line(std::string_view line, std::vector<std::string>& fields, const Location& at) {
  std::size_t count = 0;
  std::size_t pos = 0;
  for (;;) {
    if (count == fields.size()) fields.emplace_back();
    std::string& field = fields[count++];
    while (pos < line.size() && (line[pos] == ' ' || line[pos] == '\t')) ++pos;
    if (pos < line.size() && line[pos] == '"') {
      read_quoted(line, pos, field, at);
      while (pos < line.size() && (line[pos] == ' ' || line[pos] == '\t')) ++pos;
      if (pos < line.size() && line[pos] != ',')
        fail(at, "text after the closing quote of field " + std::to_string(count) +
                     "; put the whole field inside the quotes");
    } else {
      const std::size_t end = std::min(line.find(',', pos), line.size());
      field.assign(trim(line.substr(pos, end - pos)));
      pos = end;
    }
    if (pos >= line.size()) break;
    ++pos;  // past the comma
  }
  fields.resize(count);
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
  const std::string quoted = "'" + std::string(field) + "'";
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

struct Header {
  std::vector<std::string> names;
  std::size_t line = 0;
  std::size_t t = 0, u = 0, y = 0;
  std::optional<std::size_t> segment;
};

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

std::size_t require_column(const std::vector<std::string>& names, const std::string& name,
                           const char* role, const Location& at) {
  if (const auto index = find_column(names, name)) return *index;
  fail(at, "the header has no column '" + name + "' (for " + role + "); its columns are " +
               join(names) + ". Tell which columns hold t, u and y with the --columns option, " +
               "e.g. " + kColumnsHint);
}

Header read_header(LineReader& reader, std::vector<std::string>& fields, const ColumnMap& map,
                   const std::string& file) {
  const auto line = reader.next();
  if (!line)
    fail({file}, "no header row: the file is empty or holds only blank and '#' lines; it needs "
                 "a header such as t,u,y and one row per sample");
  const Location at{file, reader.line_number()};
  split_csv_line(*line, fields, at);
  // Before the column checks, which would blame the names: the whole header is one name.
  if (fields.size() == 1 && fields[0].find(';') != std::string::npos)
    fail(at, "the header '" + fields[0] + "' seems to use ';' as the delimiter; " +
                 kCommaSeparatedPoints + ". Save the file as comma-separated with '.' in numbers, " +
                 "or convert it, e.g. sed 's/,/./g; s/;/,/g'");
  check_unique(fields, at);
  Header h;
  h.names = fields;
  h.line = at.line;
  h.t = require_column(h.names, map.t, "t", at);
  h.u = require_column(h.names, map.u, "u", at);
  h.y = require_column(h.names, map.y, "y", at);
  h.segment = find_column(h.names, map.segment);
  return h;
}

struct Rows {
  std::vector<double> t, u, y;
  std::vector<std::string> segment;
  std::vector<std::size_t> line;
  int time_digits = 0;
};

// A row split into too many fields without a single decimal point: its
// numbers were most likely written with decimal commas ("0,001,1,5" for
// 0.001, 1.5).
bool split_decimal_commas(const std::vector<std::string>& fields, const Header& h) {
  return fields.size() > h.names.size() &&
         std::none_of(fields.begin(), fields.end(),
                      [](const std::string& f) { return f.find('.') != std::string::npos; });
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
                 "; check for a missing or extra comma");
  rows.t.push_back(parse_number(fields[h.t], at, h.names[h.t]));
  rows.u.push_back(parse_number(fields[h.u], at, h.names[h.u]));
  rows.y.push_back(parse_number(fields[h.y], at, h.names[h.y]));
  if (h.segment) rows.segment.push_back(fields[*h.segment]);
  rows.line.push_back(at.line);
  rows.time_digits = std::max(rows.time_digits, significant_digits(fields[h.t]));
}

void check_increasing(const Rows& rows, const std::string& file, const std::string& column) {
  for (std::size_t i = 1; i < rows.t.size(); ++i) {
    if (rows.t[i] <= rows.t[i - 1])
      fail({file, rows.line[i]}, column,
           "time " + number_text(rows.t[i]) + " is not after the previous row's " +
               number_text(rows.t[i - 1]) + " (line " + std::to_string(rows.line[i - 1]) +
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
  fail({file, rows.line[worst]}, column,
       "the time step " + number_text(rows.t[worst] - rows.t[worst - 1]) + " from line " +
           std::to_string(rows.line[worst - 1]) + " differs from the sample time " +
           number_text(dt) + " (first to last time over the sample count); samples must be " +
           "evenly spaced. Is a row missing? If the times are rounded, write more digits");
}

Measurement to_measurement(Rows& rows, const Header& h, const std::string& file) {
  const std::string& column = h.names[h.t];
  if (rows.t.empty())
    fail({file, h.line}, "the file has a header but no data rows; add one row per sample");
  if (rows.t.size() < 2)
    fail({file, rows.line[0]}, "only one sample; at least two are needed to infer the sample time");
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

// ---- writing -------------------------------------------------------------

void append_number(std::string& out, double v) {
  char buf[32];
  // Precision 17 is %.17g: enough digits for every double to read back exactly.
  const auto result = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 17);
  out.append(buf, result.ptr);
}

// Quotes a label only when the reader would otherwise split or trim it.
std::string csv_field(const std::string& s, const std::string& file) {
  if (s.find_first_of("\r\n") != std::string::npos)
    throw InputError(file + ": segment label '" + s +
                     "' contains a line break; labels must be one line");
  const bool plain = s.find_first_of(",\"") == std::string::npos && trim(s).size() == s.size();
  if (plain) return s;
  std::string out = "\"";
  for (const char c : s) out += (c == '"') ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
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

ColumnMap ColumnMap::parse(const std::string& spec) {
  ColumnMap map;
  if (trim(spec).empty()) return map;
  std::vector<std::string_view> seen;
  std::string_view rest = spec;
  for (;;) {
    const std::size_t comma = std::min(rest.find(','), rest.size());
    const std::string_view entry = trim(rest.substr(0, comma));
    const std::size_t eq = entry.find('=');
    const std::string quoted = "--columns: entry '" + std::string(entry) + "'";
    if (eq == std::string_view::npos || trim(entry.substr(eq + 1)).empty())
      throw InputError(quoted + " is not role=name; write e.g. t=t_s,u=u_N,y=y_m with roles " +
                       kRoleList);
    const std::string_view role = trim(entry.substr(0, eq));
    std::string* field = role_field(map, role);
    if (!field)
      throw InputError(quoted + ": unknown role '" + std::string(role) + "'; valid roles: " +
                       kRoleList);
    if (std::find(seen.begin(), seen.end(), role) != seen.end())
      throw InputError(quoted + ": role '" + std::string(role) + "' is given twice");
    seen.push_back(role);
    *field = std::string(trim(entry.substr(eq + 1)));
    if (comma == rest.size()) break;
    rest.remove_prefix(comma + 1);
  }
  return map;
}

ColumnMap ColumnMap::from_json(const nlohmann::json& j, const std::string& where) {
  ColumnMap map;
  if (j.is_null()) return map;
  if (!j.is_object())
    throw InputError(where + ": expected an object of column names such as "
                             "{\"t\": \"t_s\", \"u\": \"u_N\", \"y\": \"y_m\"}, got " + j.dump());
  for (const auto& [key, value] : j.items()) {
    std::string* field = role_field(map, key);
    if (!field)
      throw InputError(where + "." + key + ": unknown column role; valid roles: " + kRoleList);
    if (!value.is_string() || value.get_ref<const std::string&>().empty())
      throw InputError(where + "." + key + ": expected a column name (non-empty text), got " +
                       value.dump());
    *field = value.get<std::string>();
  }
  return map;
}

nlohmann::json ColumnMap::to_json() const {
  return {{"t", t}, {"u", u}, {"y", y}, {"segment", segment}};
}

Measurement read_measurement(const std::filesystem::path& path, const ColumnMap& columns) {
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
    split_csv_line(*line, fields, at);
    read_row(fields, header, at, rows);
  }
  return to_measurement(rows, header, file);
}

void write_measurement(const std::filesystem::path& path, const Measurement& m,
                       const std::vector<std::string>& comments) {
  const std::string file = path.string();
  check_writable(m, file);
  const bool segments = !m.segment.empty();
  std::string out = comment_lines(comments);
  out += segments ? "t,u,y,segment\n" : "t,u,y\n";
  for (Eigen::Index i = 0; i < m.t.size(); ++i) {
    append_number(out, m.t[i]);
    out += ',';
    append_number(out, m.u[i]);
    out += ',';
    append_number(out, m.y[i]);
    if (segments) out += ',' + csv_field(m.segment[static_cast<std::size_t>(i)], file);
    out += '\n';
  }
  write_file_atomic(path, out);
}

}  // namespace hystbench
