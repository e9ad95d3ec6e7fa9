#include "framework/harness/trial_result.hpp"
#include "framework/io/json_number.hpp"

#include <cmath>
#include <limits>

namespace hystbench {

nlohmann::json TrialResult::to_json() const {
  nlohmann::json trace_json = nlohmann::json::array();
  for (const auto& p : trace) trace_json.push_back({p.evaluations, number_or_null(p.best)});
  nlohmann::json j = {{"label", label},
                      {"algorithm_index", algorithm_index},
                      {"trial", trial},
                      {"seed", seed},
                      {"best", number_or_null(best)},
                      {"evaluations", evaluations},
                      {"iterations", iterations},
                      {"stop", to_string(stop)},
                      {"best_x", best_x},
                      {"wall_seconds", wall_seconds},
                      {"trace", trace_json}};
  if (!message.empty()) j["message"] = message;
  return j;
}

TrialResult TrialResult::from_json(const nlohmann::json& j) {
  TrialResult r;
  r.label = j.at("label").get<std::string>();
  r.algorithm_index = j.at("algorithm_index").get<int>();
  r.trial = j.at("trial").get<long>();
  r.seed = j.at("seed").get<std::uint64_t>();
  r.best = number_or_inf(j.at("best"));
  r.evaluations = j.at("evaluations").get<long>();
  r.iterations = j.at("iterations").get<long>();
  r.stop = stop_reason_from_string(j.at("stop").get<std::string>());
  r.best_x = j.at("best_x").get<std::vector<double>>();
  r.wall_seconds = j.at("wall_seconds").get<double>();
  for (const auto& p : j.at("trace")) r.trace.push_back({p.at(0).get<long>(), number_or_inf(p.at(1))});
  r.message = j.value("message", "");
  return r;
}

}  // namespace hystbench
