#include "framework/core/budget.hpp"

#include <array>
#include <cmath>
#include <utility>

#include "framework/core/error.hpp"
#include "framework/core/parameters.hpp"

namespace hystbench {
namespace {

constexpr std::array<std::pair<StopReason, const char*>, 7> kReasonNames{{
    {StopReason::Running, "running"},
    {StopReason::Evaluations, "evaluations"},
    {StopReason::Iterations, "iterations"},
    {StopReason::Seconds, "seconds"},
    {StopReason::Target, "target"},
    {StopReason::Converged, "converged"},
    {StopReason::Failed, "failed"},
}};

long positive_count(const nlohmann::json& j, const std::string& key, const std::string& where) {
  const auto& v = j.at(key);
  if (!v.is_number_integer() || v.get<long>() <= 0)
    throw InputError(where + "." + key + " = " + v.dump() + ": must be a positive integer");
  return v.get<long>();
}

}  // namespace

Budget Budget::from_json(const nlohmann::json& j, const std::string& where) {
  require_known_keys(j, {"evaluations", "iterations", "seconds", "target"}, where);
  Budget b;
  if (j.contains("evaluations")) b.evaluations = positive_count(j, "evaluations", where);
  if (j.contains("iterations")) b.iterations = positive_count(j, "iterations", where);
  if (j.contains("seconds")) {
    const auto& v = j.at("seconds");
    if (!v.is_number() || !(v.get<double>() > 0))
      throw InputError(where + ".seconds = " + v.dump() + ": must be a positive number");
    b.seconds = v.get<double>();
  }
  if (j.contains("target")) {
    const auto& v = j.at("target");
    if (!v.is_number() || !std::isfinite(v.get<double>()))
      throw InputError(where + ".target = " + v.dump() + ": must be a finite number");
    b.target = v.get<double>();
  }
  if (!b.evaluations && !b.iterations && !b.seconds)
    throw InputError(where + ": give at least one of \"evaluations\", \"iterations\" or "
                     "\"seconds\" (a target alone may never be reached)");
  return b;
}

nlohmann::json Budget::to_json() const {
  nlohmann::json j = nlohmann::json::object();
  if (evaluations) j["evaluations"] = *evaluations;
  if (iterations) j["iterations"] = *iterations;
  if (seconds) j["seconds"] = *seconds;
  if (target) j["target"] = *target;
  return j;
}

std::string to_string(StopReason reason) {
  for (const auto& [r, name] : kReasonNames)
    if (r == reason) return name;
  return "unknown";
}

StopReason stop_reason_from_string(const std::string& text) {
  for (const auto& [r, name] : kReasonNames)
    if (text == name) return r;
  throw InputError("unknown stop reason '" + text + "'");
}

}  // namespace hystbench
