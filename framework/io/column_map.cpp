// ColumnMap from the --columns option and from JSON: every mistake names
// the entry and the valid roles.
#include "framework/io/column_map.hpp"

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include "framework/core/error.hpp"
#include "framework/io/measurement_csv_lines.hpp"

namespace hystbench {
namespace {

using measurement_csv::trim;

constexpr const char* kRoleList = "t, u, y, segment";

std::string* role_field(ColumnMap& map, std::string_view role) {
  if (role == "t") return &map.t;
  if (role == "u") return &map.u;
  if (role == "y") return &map.y;
  if (role == "segment") return &map.segment;
  return nullptr;
}

char delimiter_from_json(const nlohmann::json& value, const std::string& where) {
  const char* known[] = {"auto", "comma", "semicolon", "tab"};
  if (value.is_string())
    for (const char* name : known)
      if (value.get<std::string>() == name) return ColumnMap::parse_delimiter(name);
  throw InputError(where + ": " + value.dump() +
                   " is not a delimiter; use \"auto\", \"comma\", \"semicolon\" or \"tab\"");
}

}  // namespace

const char* delimiter_name(char d) {
  return d == ',' ? "comma" : d == ';' ? "semicolon" : d == '\t' ? "tab" : "auto";
}

char ColumnMap::parse_delimiter(const std::string& spec) {
  const std::string_view s = spec == "\t" ? std::string_view(spec) : trim(spec);
  if (s == "auto" || s.empty()) return 0;
  if (s == "comma" || s == ",") return ',';
  if (s == "semicolon" || s == ";") return ';';
  if (s == "tab" || s == "\t" || s == "\\t") return '\t';
  throw InputError("--delimiter " + spec + ": not a delimiter; use auto, comma, semicolon or tab");
}

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
    if (key == "delimiter") {
      map.delimiter = delimiter_from_json(value, where + ".delimiter");
      continue;
    }
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
  nlohmann::json j = {{"t", t}, {"u", u}, {"y", y}, {"segment", segment}};
  if (delimiter) j["delimiter"] = delimiter_name(delimiter);
  return j;
}

}  // namespace hystbench
