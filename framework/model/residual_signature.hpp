#pragma once
// The residual statistic by which an effect says it is missing (docs/discovery.md).
// Each effect declares one in its EffectInfo, next to its parameters and
// citation: a name, how to compute it from a ResidualView and the sentence
// that cites it. `compare` and `diagnose` compute the statistic of every
// registered effect, plugins included, on the current residual, and the
// evidence for a candidate quotes its own.
//
// A statistic should fall towards its "no sign" value (0 for a correlation,
// 1 for a ratio to what chance gives) as the residual becomes white and
// independent of the input, so that a fit at the noise floor shows nothing.
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "framework/model/residual_view.hpp"

namespace hystbench {

struct SignatureValue {
  double value = std::numeric_limits<double>::quiet_NaN();  // NaN: does not apply here
  // Further numbers the sentence quotes (a lag, a frequency), by name.
  std::vector<std::pair<std::string, double>> details = {};
};

struct ResidualSignature {
  std::string name;  // the statistic as the report prints it, e.g. "corr(e, t)"
  std::function<SignatureValue(const ResidualView&)> compute = nullptr;
  // Completes "here ...": {value} and {<detail name>} stand for the numbers,
  // e.g. "the residual correlates with time (r = {value})".
  std::string sentence;
};

// The sentence with its numbers filled in (3 significant digits, whole
// numbers as such, "–" for an undefined detail); empty when the value is
// undefined.
std::string cite(const ResidualSignature& signature, const SignatureValue& v);

}  // namespace hystbench
