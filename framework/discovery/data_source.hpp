#pragma once
// A measurement named on the command line, with its column map and units,
// and the model-ready form of it (normalised, hold-out applied).
#include <string>

#include "framework/io/measurement.hpp"
#include "framework/model/holdout.hpp"
#include "framework/model/model_data.hpp"

namespace hystbench {

struct DataSource {
  std::string path;
  ColumnMap columns;
  std::string u_unit, y_unit;  // empty: taken from DATA.truth.json when it has them

  // The data file's name without its folder, for titles.
  std::string file_name() const;
  // Reads the CSV; fills empty units from the truth file beside it.
  Measurement load();
  nlohmann::json to_json() const;
};

// Normalised by `scales`, with `holdout` marked.
ModelData prepare_model_data(const Measurement& m, const SignalScales& scales,
                             const HoldoutSpec& holdout);

}  // namespace hystbench
