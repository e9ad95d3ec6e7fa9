#pragma once
// A measurement named on the command line, with its column map and units,
// and the model-ready form of it (normalised, hold-out applied).
#include <string>

#include "framework/io/measurement.hpp"
#include "framework/model/holdout.hpp"
#include "framework/model/model.hpp"
#include "framework/model/model_data.hpp"

namespace hystbench {

struct DataSource {
  std::string path;
  ColumnMap columns;
  std::string u_unit, y_unit;  // empty: from DATA.truth.json, else from the header

  // The data file's name without its folder, for titles.
  std::string file_name() const;
  // Reads the CSV; fills empty units from the truth file beside it, else
  // from the header's names.
  Measurement load();
  nlohmann::json to_json() const;
};

// Normalised by `scales`, with `holdout` marked.
ModelData prepare_model_data(const Measurement& m, const SignalScales& scales,
                             const HoldoutSpec& holdout);

// A fit needs this many estimation samples per parameter of its model, and
// never fewer than kFewestFitSamples: with fewer, the parameters follow the
// noise and nothing they say about the actuator can be trusted.
constexpr Eigen::Index kSamplesPerParameter = 10;
constexpr Eigen::Index kFewestFitSamples = 20;
Eigen::Index samples_needed(const Model& model);

// prepare_model_data() for fitting `model`: throws InputError naming the file
// and the rule when the estimation samples are too few for its parameters.
ModelData prepare_fit_data(const Measurement& m, const SignalScales& scales,
                           const HoldoutSpec& holdout, const Model& model);

}  // namespace hystbench
