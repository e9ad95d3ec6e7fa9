#include "framework/discovery/fit_record.hpp"

#include <fstream>

#include <omp.h>

#include "framework/core/error.hpp"
#include "framework/io/json_file.hpp"
#include "framework/discovery/fit_errors.hpp"
#include "framework/discovery/model_comparison.hpp"
#include "framework/report/provenance.hpp"

namespace hystbench {
namespace {

const nlohmann::json& require(const nlohmann::json& j, const std::string& key,
                              const std::string& where) {
  if (!j.contains(key)) throw InputError(where + ": missing key \"" + key + "\"");
  return j[key];
}

}  // namespace

nlohmann::json FitRecord::parameters_json() const {
  const auto names = model.parameter_names();
  const auto values = model.physical_values(x, scales);
  const auto units = model.physical_units(data.u_unit, data.y_unit);
  nlohmann::json list = nlohmann::json::array();
  for (int i = 0; i < model.dimension(); ++i)
    list.push_back({{"name", names[i]},
                    {"value", values[names[i]]},
                    {"unit", units[names[i]]},
                    {"normalised", x[i]},
                    {"doc", model.parameter(i).doc}});
  return list;
}

nlohmann::json FitRecord::to_json() const {
  nlohmann::json effects = nlohmann::json::array();
  for (const auto& name : model.effects()) {
    const auto& info = EffectRegistry::instance().find(name, "effect");
    effects.push_back({{"name", name}, {"stage", stage_name(info.stage)}, {"summary", info.summary}});
  }
  nlohmann::json j = {{"format", "hystbench-fit/1"},
                      {"model", model.text()},
                      {"effects", effects},
                      {"parameters", parameters_json()},
                      {"scales", scales.to_json()},
                      {"substeps", model.substeps()},
                      {"data", data.to_json()},
                      {"holdout", holdout.text()}};
  // Written only when it is not the default, so that the files of default
  // fits are what they were before the hold was a choice.
  if (model.input_hold() != InputHold::Spline) j["input_hold"] = to_string(model.input_hold());
  for (const auto& [key, value] : details.items()) j[key] = value;
  return j;
}

FitRecord FitRecord::read(const std::filesystem::path& path) {
  const std::string where = path.string();
  const nlohmann::json j = read_json_file(path, "fit file");
  if (j.value("format", "") != "hystbench-fit/1")
    throw InputError(where + ": not a fit file written by `hystbench fit` (format key)");
  FitRecord r{Model::parse(require(j, "model", where).get<std::string>(), where + " model")};
  r.model.set_substeps(j.value("substeps", 0));
  r.model.set_input_hold(parse_input_hold(j.value("input_hold", "spline"), where + " input_hold"));
  r.scales = SignalScales::from_json(require(j, "scales", where), where + " scales");
  const auto& data = require(j, "data", where);
  r.data.path = data.value("file", "");
  r.data.columns = ColumnMap::from_json(data.value("columns", nlohmann::json::object()),
                                        where + " data.columns");
  r.data.u_unit = data.value("units", nlohmann::json::object()).value("u", "");
  r.data.y_unit = data.value("units", nlohmann::json::object()).value("y", "");
  r.holdout = HoldoutSpec::parse(j.value("holdout", "auto"), where + " holdout");
  const auto names = r.model.parameter_names();
  r.x = r.model.neutral();
  std::vector<bool> seen(names.size(), false);
  for (const auto& p : require(j, "parameters", where)) {
    const auto it = std::find(names.begin(), names.end(), p.value("name", ""));
    if (it == names.end() || !p.contains("normalised") || !p["normalised"].is_number())
      throw InputError(where + ": parameter entry " + p.dump() + " does not belong to model " +
                       r.model.text());
    r.x[it - names.begin()] = p["normalised"].get<double>();
    seen[it - names.begin()] = true;
  }
  for (std::size_t i = 0; i < names.size(); ++i)
    if (!seen[i]) throw InputError(where + ": missing parameter '" + names[i] + "'");
  for (const auto& key : {"errors", "metrics", "fit", "seed", "provenance"})
    if (j.contains(key)) r.details[key] = j[key];
  return r;
}

FitRecord make_fit_record(const Model& model, const Eigen::VectorXd& x, const ModelData& data,
                          const DataSource& source, const HoldoutSpec& holdout, std::uint64_t seed) {
  FitRecord r{model, x, data.scales, source, holdout};
  Eigen::VectorXd y;
  const bool stable = simulate_physical(model, x, data, y);
  const nlohmann::json metrics =
      stable ? to_json(part_metrics(comparison_input(data, y, source.u_unit, source.y_unit)))
             : nlohmann::json();
  r.details = {{"errors", fit_errors(model, x, data).to_json()},
               {"metrics", metrics},
               {"seed", seed},
               {"provenance", provenance(omp_get_max_threads(), seed)}};
  return r;
}

namespace {

ModelData repeated(const ModelData& d, int periods) {
  const Eigen::Index n = d.size();
  ModelData r = d;
  r.t.resize(n * periods);
  r.u.resize(n * periods);
  r.y.resize(n * periods);
  r.estimation.resize(n * periods);
  r.segment.clear();
  for (int p = 0; p < periods; ++p) {
    r.t.segment(p * n, n) = d.t.array() + double(p * n) * d.sample_time;
    r.u.segment(p * n, n) = d.u;
    r.y.segment(p * n, n) = d.y;
    r.estimation.segment(p * n, n) = d.estimation;
  }
  return r;
}

}  // namespace

bool simulate_physical(const Model& model, const Eigen::VectorXd& x, const ModelData& data,
                       Eigen::VectorXd& y, int periods) {
  if (periods > 1) {
    Eigen::VectorXd all;
    if (!model.simulate(x, repeated(data, periods), all)) return false;
    y = all.tail(data.size()) * data.scales.y;
    return true;
  }
  if (!model.simulate(x, data, y)) return false;
  y *= data.scales.y;
  return true;
}

}  // namespace hystbench
