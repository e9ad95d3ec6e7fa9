// Splitting one line of a measurement CSV into fields, quoted or not.
#include "framework/io/measurement_csv_lines.hpp"

#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace hystbench::measurement_csv {
namespace {

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

}  // namespace

void split_csv_line(std::string_view line, std::vector<std::string>& fields, const Location& at,
                    char delimiter) {
  // A tab is a blank around fields unless it separates them.
  const auto blank = [delimiter](char c) { return c == ' ' || (c == '\t' && delimiter != '\t'); };
  std::size_t count = 0;
  std::size_t pos = 0;
  for (;;) {
    if (count == fields.size()) fields.emplace_back();
    std::string& field = fields[count++];
    while (pos < line.size() && blank(line[pos])) ++pos;
    if (pos < line.size() && line[pos] == '"') {
      read_quoted(line, pos, field, at);
      while (pos < line.size() && blank(line[pos])) ++pos;
      if (pos < line.size() && line[pos] != delimiter)
        fail(at, "text after the closing quote of field " + std::to_string(count) +
                     "; put the whole field inside the quotes");
    } else {
      const std::size_t end = std::min(line.find(delimiter, pos), line.size());
      field.assign(trim(line.substr(pos, end - pos)));
      pos = end;
    }
    if (pos >= line.size()) break;
    ++pos;  // past the delimiter
  }
  fields.resize(count);
}

char detect_delimiter(std::string_view header) {
  header = trim(header);
  const auto count = [header](char c) { return std::count(header.begin(), header.end(), c); };
  char best = ',';
  for (const char c : {';', '\t'})
    if (count(c) > count(best)) best = c;
  return best;
}

}  // namespace hystbench::measurement_csv
