#include "framework/discovery/data_source.hpp"

#include <filesystem>

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

}  // namespace hystbench
