#include "framework/harness/trial_range.hpp"

#include <cctype>

#include "framework/core/error.hpp"

namespace hystbench {
namespace {

bool all_digits(const std::string& s) {
  if (s.empty() || s.size() > 12) return false;
  for (char c : s)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  return true;
}

}  // namespace

TrialRange parse_trial_range(const std::string& text, long trials, const std::string& option) {
  const auto colon = text.find(':');
  const std::string where = option + " " + text + ": ";
  if (colon == std::string::npos || !all_digits(text.substr(0, colon)) ||
      !all_digits(text.substr(colon + 1)))
    throw InputError(where + "expected FROM:TO, 0-based trial indices with TO exclusive, e.g. 0:5");
  const TrialRange r{std::stol(text.substr(0, colon)), std::stol(text.substr(colon + 1))};
  if (r.end <= r.first) throw InputError(where + "TO must be greater than FROM");
  if (r.end > trials)
    throw InputError(where + "TO is past the experiment's " + std::to_string(trials) + " trials");
  return r;
}

}  // namespace hystbench
