#include "framework/discovery/ladder_checkpoint.hpp"

#include <fstream>

#include "framework/core/error.hpp"
#include "framework/discovery/beyond_catalog.hpp"
#include "framework/discovery/comparison.hpp"
#include "framework/discovery/fit_record.hpp"
#include "framework/discovery/model_comparison.hpp"

namespace hystbench {
namespace {

constexpr const char* kFormat = "hystbench-ladder-checkpoint/1";

nlohmann::json vector_json(const Eigen::VectorXd& x) {
  return std::vector<double>(x.data(), x.data() + x.size());
}

Eigen::VectorXd vector_of(const nlohmann::json& j, const Model& model, const std::string& where) {
  const auto v = j.get<std::vector<double>>();
  if (int(v.size()) != model.dimension())
    throw InputError(where + ": " + std::to_string(v.size()) + " parameters for model " +
                     model.text() + ", which has " + std::to_string(model.dimension()));
  return Eigen::Map<const Eigen::VectorXd>(v.data(), Eigen::Index(v.size()));
}

Model model_of(const nlohmann::json& j, const DiscoverOptions& o, const std::string& where) {
  Model m = Model::parse(j.get<std::string>(), where);
  m.set_substeps(o.substeps);  // a model text does not carry them
  m.set_input_hold(o.input_hold);
  return m;
}

// The first key (dotted path) at which a and b differ; "" when equal.
std::string first_difference(const nlohmann::json& a, const nlohmann::json& b,
                             const std::string& path = "") {
  if (a.is_object() && b.is_object()) {
    for (const auto& [key, value] : a.items()) {
      const std::string sub = path.empty() ? key : path + "." + key;
      if (!b.contains(key)) return sub;
      if (auto d = first_difference(value, b[key], sub); !d.empty()) return d;
    }
    for (const auto& [key, value] : b.items())
      if (!a.contains(key)) return path.empty() ? key : path + "." + key;
    return "";
  }
  return a == b ? "" : (path.empty() ? "(top level)" : path);
}

Diagnosis restored_diagnosis(const nlohmann::json& j, const ModelData& data,
                             const DiscoverOptions& o, const std::string& where) {
  const Model model = model_of(j.at("model"), o, where + " model");
  Diagnosis d{model, vector_of(j.at("x"), model, where + " x"), {}};
  d.errors = fit_errors(d.model, d.x, data);
  d.bic = bic(d.errors.sse, d.errors.n_estimation, d.model.dimension());
  Eigen::VectorXd y;
  if (!simulate_physical(d.model, d.x, data, y)) y = Eigen::VectorXd::Zero(data.size());
  d.where = compare_signals(comparison_input(data, std::move(y), o.diagnose.u_unit, o.diagnose.y_unit));
  d.completeness = assess_completeness(d.errors, d.where);
  // What the diagnosis added on top of the assessment when no effect
  // captured what was left (describe_beyond_catalog): kept, not recomputed,
  // because it was judged on candidates the checkpoint does not keep.
  if (j.contains("beyond")) {
    d.beyond = BeyondCatalog::from_json(j.at("beyond"));
    d.completeness.kind = j.at("completeness_kind").get<std::string>();
    d.completeness.reason = j.at("completeness_reason").get<std::string>();
  }
  d.check = check_model(d.model, d.x, data, o.diagnose.u_unit, o.diagnose.y_unit);
  d.optimum = OptimumCheck::from_json(j.at("optimum"));
  d.verdict = j.at("verdict").get<std::string>();
  d.close_call = {j.at("close_call").at("close").get<bool>(),
                  j.at("close_call").at("reason").get<std::string>(),
                  j.at("close_call").at("runner_up").get<std::string>()};
  if (const auto& w = j.at("winner"); !w.is_null()) {
    Candidate c{w.at("effect").get<std::string>(), model_of(w.at("model"), o, where + " winner"), {}, {}};
    c.x = vector_of(w.at("x"), c.model, where + " winner x");
    c.after = fit_errors(c.model, c.x, data);
    c.evidence = w.at("evidence").get<std::string>();
    c.significant = true;
    d.candidates.push_back(std::move(c));
  }
  d.options = o.diagnose.to_json();
  return d;
}

nlohmann::json diagnosis_json(const Diagnosis& d) {
  nlohmann::json winner;
  if (const Candidate* w = d.winner())
    winner = {{"effect", w->effect}, {"model", w->model.text()}, {"x", vector_json(w->x)},
              {"evidence", w->evidence}};
  return {{"model", d.model.text()},
          {"x", vector_json(d.x)},
          {"verdict", d.verdict},
          {"close_call", {{"close", d.close_call.close},
                          {"reason", d.close_call.reason},
                          {"runner_up", d.close_call.runner_up}}},
          {"optimum", d.optimum.to_json()},
          {"beyond", d.beyond.to_json()},
          {"completeness_kind", d.completeness.kind},
          {"completeness_reason", d.completeness.reason},
          {"winner", winner}};
}

}  // namespace

nlohmann::json checkpoint_json(const Ladder& ladder, const nlohmann::json& context) {
  nlohmann::json steps = nlohmann::json::array(), diagnoses = nlohmann::json::array();
  for (const auto& s : ladder.steps)
    steps.push_back({{"added", s.added},
                     {"removed", s.removed},
                     {"evidence", s.evidence},
                     {"attribution", s.attribution},
                     {"nesting_refits", to_json(s.nesting)},
                     {"sub_models", to_json(s.sub_models)}});
  for (const auto& d : ladder.diagnoses) diagnoses.push_back(diagnosis_json(d));
  return {{"format", kFormat},
          {"context", context},
          {"steps", steps},
          {"diagnoses", diagnoses},
          {"stopped_by_limit", ladder.stopped_by_limit}};
}

Ladder read_checkpoint(const std::filesystem::path& dir, const nlohmann::json& context,
                       const ModelData& data, const DiscoverOptions& o, const std::string& option) {
  const auto path = dir / "checkpoint.json";
  const std::string where = path.string();
  const bool resume = option == "--resume";
  std::ifstream in(path);
  if (!in)
    throw InputError(option + ": " + where + " does not exist; " +
                     (resume ? "run discover without --resume first"
                             : "run `hystbench diagnose --model START --out " + dir.string() +
                                   "` with discover's data and options first"));
  Ladder ladder;
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    if (j.value("format", "") != kFormat) throw InputError(where + ": not a discover checkpoint");
    if (const auto d = first_difference(j.at("context"), context); !d.empty())
      throw InputError(option + ": " + where + " was made with another " + d +
                       (resume ? "; resume with the same data and options, or start again without --resume"
                               : "; diagnose with discover's data, start model and options, or run "
                                 "discover without --diagnosis"));
    const auto& steps = j.at("steps");
    const auto& diagnoses = j.at("diagnoses");
    if (steps.empty() || steps.size() != diagnoses.size())
      throw InputError(where + ": steps and diagnoses do not match");
    for (std::size_t k = 0; k < steps.size(); ++k) {
      const std::string at = where + " step " + std::to_string(k);
      Diagnosis d = restored_diagnosis(diagnoses[k], data, o, at);
      LadderStep s{d.model, d.x, d.errors};
      s.bic = d.bic;
      s.added = steps[k].at("added").get<std::string>();
      s.removed = steps[k].at("removed").get<std::vector<std::string>>();
      s.evidence = steps[k].at("evidence").get<std::string>();
      s.attribution = steps[k].at("attribution").get<std::string>();
      // Checkpoints made before the nesting rule have neither.
      s.nesting = nesting_refits_from_json(steps[k].value("nesting_refits", nlohmann::json::array()));
      s.sub_models = tried_sub_models_from_json(steps[k].value("sub_models", nlohmann::json::array()));
      ladder.steps.push_back(std::move(s));
      ladder.diagnoses.push_back(std::move(d));
    }
    ladder.stopped_by_limit = j.at("stopped_by_limit").get<bool>();
  } catch (const nlohmann::json::exception& e) {
    throw InputError(where + ": unreadable checkpoint: " + e.what());
  }
  ladder.restored = ladder.diagnoses.size();
  return ladder;
}

}  // namespace hystbench
