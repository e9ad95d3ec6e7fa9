#pragma once
// A tracking experiment (docs/tracking.md#experiment-file): the simulated
// plant, the identified model the controllers are built from, the weights,
// the controllers and the references. Read and checked whole before
// anything runs.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "framework/tracking/identified_model.hpp"
#include "framework/tracking/hinf_design.hpp"
#include "framework/tracking/tracking_loop.hpp"
#include "framework/tracking/tracking_reference.hpp"

namespace hystbench {

struct UncertaintySpec {
  // "residual" (from the identification residual over `records`), "seed"
  // (seed 002's eq. 21) or "given" (num/den in s).
  std::string kind = "residual";
  std::vector<std::filesystem::path> records;
  double margin = 2.0, rise = 4.0;
  std::vector<double> num, den;
};

struct TrackingExperiment {
  std::string name, description;
  nlohmann::json source;
  std::filesystem::path base_dir;
  double sample_time = 1e-4;
  nlohmann::json plant;  // a model_stream spec, resolved when run
  std::string plant_description;
  SensorSettings sensor;
  double u_min = 0.0, u_max = 150.0;
  IdentifiedSource identified;
  std::shared_ptr<IdentifiedModel> identified_model;  // at the loop's rate, at rest: copy before use
  int p = 2, q = 1;
  UncertaintySpec uncertainty;
  DesignOptions design;
  std::vector<TrackingController> controllers;  // H∞ feedback filled in by the design
  std::vector<TrackingReference> references;
  ScoreWindow window;
  double inverse_tolerance = 1e-6;
  std::string u_unit = "V", y_unit = "µm";
  std::uint64_t seed = 1;

  // Throws InputError naming the key for anything wrong in the file.
  static TrackingExperiment load(const std::filesystem::path& path);
  static TrackingExperiment from_json(const nlohmann::json& j, const std::filesystem::path& base_dir,
                                      const std::string& where);
};

}  // namespace hystbench
