#include "framework/io/header_names.hpp"

#include <algorithm>
#include <cctype>
#include <span>
#include <utility>

#include "framework/core/text.hpp"
#include "framework/io/measurement_csv_lines.hpp"

namespace hystbench {
namespace {

// Units accepted after '_', a blank or '/' ("time_s", "Weg um", "t/ms").
// Bracketed units are taken as written, so this list only has to keep a
// name such as "input_signal" whole.
constexpr std::string_view kKnownUnits[] = {
    "s",  "ms", "us", "µs", "ns", "min", "h",  "V",   "mV",  "kV", "uV", "µV",
    "A",  "mA", "uA", "µA", "m",  "mm",  "um", "µm",  "nm",  "cm", "N",  "mN",
    "kN", "Pa", "kPa", "MPa", "bar", "rad", "deg", "Hz"};

constexpr std::string_view kTimeNames[] = {"t", "time", "zeit", "timestamp", "times"};
constexpr std::string_view kInputNames[] = {
    "u", "input", "voltage", "spannung", "eingang", "u_in", "v_in", "vin", "excitation"};
constexpr std::string_view kOutputNames[] = {
    "y", "output", "displacement", "weg", "position", "ausgang", "auslenkung", "y_out", "stroke"};

using measurement_csv::trim;

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = char(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

bool known_unit(std::string_view unit) {
  return std::find(std::begin(kKnownUnits), std::end(kKnownUnits), unit) != std::end(kKnownUnits);
}

// "um" and "us" are how a keyboard without µ writes micro.
std::string spelled(std::string_view unit) {
  if (unit.size() == 2 && unit[0] == 'u' && known_unit(unit)) return "µ" + std::string(unit.substr(1));
  return std::string(unit);
}

std::span<const std::string_view> names_of(ColumnRole role) {
  switch (role) {
    case ColumnRole::t: return kTimeNames;
    case ColumnRole::u: return kInputNames;
    case ColumnRole::y: return kOutputNames;
  }
  return {};
}

}  // namespace

HeaderName split_unit(std::string_view name) {
  name = trim(name);
  for (const auto& [open, close] : {std::pair{'[', ']'}, std::pair{'(', ')'}}) {
    const auto at = name.rfind(open);
    if (!name.empty() && name.back() == close && at != std::string_view::npos && at > 0) {
      const auto unit = trim(name.substr(at + 1, name.size() - at - 2));
      return {std::string(trim(name.substr(0, at))), spelled(unit)};
    }
  }
  const auto at = name.find_last_of("_ /");
  if (at != std::string_view::npos && at > 0 && known_unit(name.substr(at + 1)))
    return {std::string(trim(name.substr(0, at))), spelled(name.substr(at + 1))};
  return {std::string(name), {}};
}

const char* role_name(ColumnRole role) {
  switch (role) {
    case ColumnRole::t: return "t";
    case ColumnRole::u: return "u";
    case ColumnRole::y: return "y";
  }
  return "?";
}

std::string role_synonyms(ColumnRole role) {
  const auto names = names_of(role);
  return join(std::vector<std::string>(names.begin(), names.end()));
}

std::vector<std::size_t> columns_named_as(const std::vector<std::string>& names, ColumnRole role) {
  const auto synonyms = names_of(role);
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::string base = lower(split_unit(names[i]).base);
    if (std::find(synonyms.begin(), synonyms.end(), base) != synonyms.end()) out.push_back(i);
  }
  return out;
}

}  // namespace hystbench
