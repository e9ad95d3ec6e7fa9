#pragma once
// The column map of a measurement CSV, apart from the reader because the
// command line and the experiment files name columns too.
#include <nlohmann/json.hpp>
#include <string>

namespace hystbench {

// Which header names hold t, u, y and segment, and what separates fields.
// A role left at its default name is also found by a common name with a
// unit ("Zeit [s]", "voltage_V"; framework/io/header_names.hpp).
struct ColumnMap {
  std::string t = "t";
  std::string u = "u";
  std::string y = "y";
  std::string segment = "segment";
  char delimiter = 0;  // ',', ';' or '\t'; 0: the header's most frequent of the three

  // "auto", "comma", "semicolon", "tab" or the character itself; throws
  // InputError naming the option and the valid values.
  static char parse_delimiter(const std::string& spec);

  // "t=t_s,u=u_N,y=y_m" (any subset, any order). Throws InputError naming
  // the bad entry and the valid roles (t, u, y, segment).
  static ColumnMap parse(const std::string& spec);
  // {"t": "t_s", "u": "u_N", "y": "y_m", "delimiter": "tab"} (any subset);
  // `where` names the JSON key.
  static ColumnMap from_json(const nlohmann::json& j, const std::string& where);
  nlohmann::json to_json() const;
};

// "comma", "semicolon", "tab", or "auto" for 0.
const char* delimiter_name(char delimiter);

}  // namespace hystbench
