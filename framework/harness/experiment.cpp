#include "framework/harness/experiment.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>

#include "framework/core/error.hpp"
#include "framework/core/parameters.hpp"
#include "framework/core/registry.hpp"
#include "framework/core/text.hpp"
#include "framework/local/nlopt_search.hpp"

namespace hystbench {
namespace {

// What a missing top-level key could look like, for the message.
std::string example_of(const std::string& key) {
  if (key == "name") return R"("name": "demo")";
  if (key == "problem") return R"("problem": {"type": "function", "name": "sphere", "dimension": 10})";
  if (key == "budget") return R"("budget": {"evaluations": 5000})";
  if (key == "trials") return R"("trials": 10)";
  return R"("algorithms": [{"name": "de"}])";
}

const nlohmann::json& required(const nlohmann::json& j, const std::string& key) {
  if (!j.contains(key))
    throw InputError("missing key \"" + key + "\"; add it, e.g. " + example_of(key));
  return j.at(key);
}

// j[key] as text, or `fallback` when the key is absent; `shown_as` names the
// key in the message when the value is not text.
std::string text_or(const nlohmann::json& j, const std::string& key, const std::string& fallback,
                    const std::string& shown_as) {
  if (!j.contains(key)) return fallback;
  const auto& v = j.at(key);
  if (!v.is_string()) throw InputError(shown_as + " = " + v.dump() + ": expected text (a JSON string)");
  return v.get<std::string>();
}

long positive_integer(const nlohmann::json& v, const std::string& key) {
  if (!v.is_number_integer() || v.get<long>() <= 0)
    throw InputError(key + " = " + v.dump() + ": must be a positive integer");
  return v.get<long>();
}

PolishSpec read_polish(const nlohmann::json& j, const std::string& where) {
  require_known_keys(j, {"algorithm", "fraction", "repeat"}, where);
  PolishSpec p;
  p.algorithm = text_or(j, "algorithm", p.algorithm, where + ".algorithm");
  std::vector<std::string> local = nlopt_local_algorithms();
  local.push_back(PolishSpec::kLevenbergMarquardt);
  if (std::find(local.begin(), local.end(), p.algorithm) == local.end())
    throw InputError(where + ".algorithm = \"" + p.algorithm + "\": use a local NLopt method or " +
                     PolishSpec::kLevenbergMarquardt + ": " + join(local));
  const auto repeat = j.value("repeat", nlohmann::json(p.repeat));
  if (!repeat.is_boolean()) throw InputError(where + ".repeat = " + repeat.dump() + ": must be true or false");
  p.repeat = repeat.get<bool>();
  const auto fraction = j.value("fraction", nlohmann::json(p.fraction));
  if (!fraction.is_number() || !(fraction.get<double>() > 0 && fraction.get<double>() < 1))
    throw InputError(where + ".fraction = " + fraction.dump() + ": must be between 0 and 1 (exclusive)");
  p.fraction = fraction.get<double>();
  return p;
}

AlgorithmSpec read_algorithm(const nlohmann::json& a, std::size_t index) {
  const std::string where = "algorithms[" + std::to_string(index) + "]";
  require_known_keys(a, {"name", "label", "params", "polish"}, where);
  if (!a.contains("name") || !a["name"].is_string())
    throw InputError(where + ".name: missing; give the optimizer's name (see `hystbench list`)");
  AlgorithmSpec spec;
  spec.name = a["name"].get<std::string>();
  spec.label = text_or(a, "label", spec.name, where + ".label");
  const auto& info = OptimizerRegistry::instance().find(spec.name, where + ".name");
  const auto given = a.value("params", nlohmann::json::object());
  const std::string params_key = where + " (" + spec.label + ").params";
  spec.params = validate_params(info.params, given, params_key).json();
  // Built once now, so that checks across parameters (elites < np, ...)
  // fail before any output exists rather than in every trial.
  try {
    info.create(Params(spec.params));
  } catch (const InputError& e) {
    throw InputError(params_key + ": " + e.what());
  }
  if (a.contains("polish")) spec.polish = read_polish(a["polish"], where + ".polish");
  return spec;
}

}  // namespace

Experiment Experiment::from_json(const nlohmann::json& j, const std::string& where) {
  try {
    require_known_keys(j, {"name", "description", "problem", "budget", "trials", "seed", "algorithms", "table_layout"},
                       "top level");
    Experiment e;
    const auto& name = required(j, "name");
    if (!name.is_string() || name.get<std::string>().empty())
      throw InputError("name: expected a non-empty string");
    e.name = name.get<std::string>();
    e.description = text_or(j, "description", "", "description");
    e.table_layout = text_or(j, "table_layout", "default", "table_layout");
    if (e.table_layout != "default" && e.table_layout != "seed")
      throw InputError("table_layout = \"" + e.table_layout + "\": give \"default\" (one column per statistic) or "
                       "\"seed\" (MEDE's Table 1, with Best beside f_min)");
    e.problem = required(j, "problem");
    problem_options(e.problem);  // its keys and their types, before anything runs
    e.budget = Budget::from_json(required(j, "budget"), "budget");
    e.trials = positive_integer(required(j, "trials"), "trials");
    const auto seed = j.value("seed", nlohmann::json(1));
    if (!seed.is_number_integer() || seed.get<long long>() < 0) throw InputError("seed = " + seed.dump() + ": must be a non-negative integer");
    e.seed = seed.get<std::uint64_t>();
    const auto& algorithms = required(j, "algorithms");
    if (!algorithms.is_array() || algorithms.empty())
      throw InputError("algorithms: expected a non-empty list of {\"name\": ..., \"params\": {...}}");
    std::set<std::string> labels;
    for (std::size_t i = 0; i < algorithms.size(); ++i) {
      e.algorithms.push_back(read_algorithm(algorithms[i], i));
      if (e.algorithms.back().polish && !e.budget.evaluations)
        throw InputError("algorithms[" + std::to_string(i) + "].polish needs an evaluation budget "
                         "(budget.evaluations): it takes the last fraction of it");
      if (!labels.insert(e.algorithms.back().label).second)
        throw InputError("algorithms[" + std::to_string(i) + "].label \"" + e.algorithms.back().label +
                         "\" is used twice; give each algorithm a distinct label");
    }
    return e;
  } catch (const InputError& err) {
    throw InputError(where + ": " + err.what());
  }
}

Experiment Experiment::load(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError(file.string() + ": cannot open the experiment file; check the path");
  Experiment e = parse(in, file.string());
  e.base_dir = file.parent_path();
  return e;
}

Experiment Experiment::parse(std::istream& in, const std::string& where) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& err) {  // syntax, or a number beyond a double
    throw InputError(where + ": not valid JSON: " + err.what());
  }
  return from_json(j, where);
}

nlohmann::json Experiment::to_json() const {
  nlohmann::json algs = nlohmann::json::array();
  for (const auto& a : algorithms) {
    nlohmann::json j = {{"name", a.name}, {"label", a.label}, {"params", a.params}};
    if (a.polish) {
      j["polish"] = {{"algorithm", a.polish->algorithm}, {"fraction", a.polish->fraction}};
      // Written only when set, so experiments without it keep their identity
      // (campaign.json) from before the option existed.
      if (a.polish->repeat) j["polish"]["repeat"] = true;
    }
    algs.push_back(j);
  }
  nlohmann::json j = {{"name", name},       {"problem", problem}, {"budget", budget.to_json()},
                      {"trials", trials},   {"seed", seed},       {"algorithms", algs}};
  if (!description.empty()) j["description"] = description;
  if (table_layout != "default") j["table_layout"] = table_layout;
  return j;
}

}  // namespace hystbench
