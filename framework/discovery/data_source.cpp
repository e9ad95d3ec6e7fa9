#include "framework/discovery/data_source.hpp"

#include <algorithm>
#include <filesystem>

#include "framework/core/error.hpp"
#include "framework/io/truth_file.hpp"

namespace hystbench {

Measurement DataSource::load() {
  Measurement m = read_measurement(path, columns);
  const auto truth = read_truth(path);
  const auto units = truth.value("units", nlohmann::json::object());
  if (u_unit.empty() && units.is_object() && units.value("u", nlohmann::json()).is_string())
    u_unit = units["u"].get<std::string>();
  if (y_unit.empty() && units.is_object() && units.value("y", nlohmann::json()).is_string())
    y_unit = units["y"].get<std::string>();
  if (u_unit.empty()) u_unit = m.u_unit;
  if (y_unit.empty()) y_unit = m.y_unit;
  return m;
}

std::string DataSource::file_name() const {
  return std::filesystem::path(path).filename().string();
}

nlohmann::json DataSource::to_json() const {
  return {{"file", path}, {"columns", columns.to_json()}, {"units", {{"u", u_unit}, {"y", y_unit}}}};
}

ModelData prepare_model_data(const Measurement& m, const SignalScales& scales,
                             const HoldoutSpec& holdout) {
  ModelData d(m, scales);
  apply_holdout(d, holdout);
  return d;
}

Eigen::Index samples_needed(const Model& model) {
  return std::max(kSamplesPerParameter * model.dimension(), kFewestFitSamples);
}

ModelData prepare_fit_data(const Measurement& m, const SignalScales& scales,
                           const HoldoutSpec& holdout, const Model& model) {
  ModelData d = prepare_model_data(m, scales, holdout);
  const Eigen::Index have = d.estimation_count(), need = samples_needed(model);
  if (have >= need) return d;
  const auto count = [](Eigen::Index n, const char* what) {
    return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
  };
  const std::string held =
      d.heldout_count() ? " (" + std::to_string(d.size()) + " in the file, " +
                              std::to_string(d.heldout_count()) + " held out)"
                        : "";
  throw InputError(m.source + ": " + count(have, "sample") + " to fit" + held + ", but the model " +
                   model.text() + " has " + count(model.dimension(), "parameter") +
                   " and needs at least " + std::to_string(need) + " (" +
                   std::to_string(kSamplesPerParameter) + " per parameter, " +
                   std::to_string(kFewestFitSamples) + " at the least); give more data" +
                   (d.heldout_count() ? ", hold out fewer samples (--holdout)" : "") +
                   " or a smaller model");
}

}  // namespace hystbench
