#pragma once
// The text layer of a measurement CSV, shared by its reader, writer and
// checks: blanks, content lines, fields, and where in the file an error is.
#include <algorithm>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "framework/core/error.hpp"

namespace hystbench::measurement_csv {

// Where a problem is. Messages are only built when one occurs, so reading a
// long file costs nothing for it.
struct Location {
  const std::string& file;
  std::size_t line = 0;  // 1-based physical line; 0 means the whole file
  const char* unit = "line";  // what `line` counts: "sample" in a MAT file
};

[[noreturn]] inline void fail(const Location& at, const std::string& what) {
  std::string where = at.file;
  if (at.line > 0) where += ", " + std::string(at.unit) + " " + std::to_string(at.line);
  throw InputError(where + ": " + what);
}

[[noreturn]] inline void fail(const Location& at, const std::string& column,
                              const std::string& what) {
  fail(at, "column '" + column + "': " + what);
}

// The field without the blanks (spaces, tabs) around it.
inline std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

// Hands out the lines that carry content: blank lines and '#' or '%'
// comments (a DAQ program's or MATLAB's header) are skipped, but still
// counted so that messages point at the right line.
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
      if (!body.empty() && body.front() != '#' && body.front() != '%') return line;
    }
    return std::nullopt;
  }

  std::size_t line_number() const { return line_; }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_ = 0;
};

// Splits one CSV line at `delimiter` (',', ';' or '\t') into fields without
// quotes and surrounding blanks. `fields` is reused from line to line so a
// long file does not allocate per row.
void split_csv_line(std::string_view line, std::vector<std::string>& fields, const Location& at,
                    char delimiter = ',');

// The delimiter a header line uses: the most frequent of ',', ';' and tab
// (',' on a tie, then ';'), so that tabs as blanks around commas stay blanks.
char detect_delimiter(std::string_view header);

}  // namespace hystbench::measurement_csv
