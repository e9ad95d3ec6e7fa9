#pragma once
// The column map of a measurement CSV, apart from the reader because the
// command line and the experiment files name columns too.
#include <nlohmann/json.hpp>
#include <string>

namespace hystbench {

// Which header names hold t, u, y and segment.
struct ColumnMap {
  std::string t = "t";
  std::string u = "u";
  std::string y = "y";
  std::string segment = "segment";

  // "t=t_s,u=u_N,y=y_m" (any subset, any order). Throws InputError naming
  // the bad entry and the valid roles (t, u, y, segment).
  static ColumnMap parse(const std::string& spec);
  // {"t": "t_s", "u": "u_N", "y": "y_m"}; `where` names the JSON key.
  static ColumnMap from_json(const nlohmann::json& j, const std::string& where);
  nlohmann::json to_json() const;
};

}  // namespace hystbench
