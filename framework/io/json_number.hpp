#pragma once
// JSON has no infinity: a fitness of +inf (diverged, or nothing evaluated)
// is written as null and read back as +inf.
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

namespace hystbench {

inline nlohmann::json number_or_null(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json();
}

inline double number_or_inf(const nlohmann::json& j) {
  return j.is_null() ? std::numeric_limits<double>::infinity() : j.get<double>();
}

}  // namespace hystbench
