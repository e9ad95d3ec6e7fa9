#include "framework/cli/number_range.hpp"

#include <cmath>

#include "framework/core/text.hpp"

namespace hystbench::cli {
namespace {

// For --help: "0 to 1000", "0 or more" (ASCII, which keeps the help's columns aligned).
std::string bounds_text(double lowest, double highest) {
  if (std::isinf(highest)) return number_text(lowest) + " or more";
  if (std::isinf(lowest)) return number_text(highest) + " or less";
  return number_text(lowest) + " to " + number_text(highest);
}

}  // namespace

CLI::Validator number_range(double lowest, double highest, const std::string& hint) {
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        double value = 0;
        if (!CLI::detail::lexical_cast(text, value) || std::isnan(value))
          return "'" + text + "' is not a number; " + hint;
        if (value < lowest || value > highest) return text + " is not allowed; " + hint;
        return {};
      },
      bounds_text(lowest, highest));
}

}  // namespace hystbench::cli
