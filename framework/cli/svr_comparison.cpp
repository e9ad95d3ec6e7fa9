#include "framework/cli/svr_comparison.hpp"

#include <cmath>

#include "framework/cli/comparison_output.hpp"
#include "framework/core/error.hpp"
#include "framework/core/text.hpp"
#include "framework/svr/svr_model.hpp"

namespace hystbench::cli {

Comparison compare_svr_model(const nlohmann::json& file, const std::string& path, const DataOptions& data,
                             const OutputOptions& output, const CLI::App& cmd, const std::string& mat) {
  const SvrHammerstein model = SvrHammerstein::from_json(file, path);
  if (data.initial_state == "held")
    throw InputError("--initial-state held: an SVR model starts from the record's first measured "
                     "samples, not from a held level; leave the option out");
  DataSource source = data.source();
  const Measurement m = source.load();
  const double trained = file.value("sample_time", 0.0);
  if (trained > 0.0 && std::abs(m.sample_time - trained) > 1e-6 * trained)
    throw InputError(data.data + " is sampled every " + number_text(m.sample_time) + " s but " + path +
                     " was trained on samples every " + number_text(trained) +
                     " s; the model's lags are in samples, so resample the data to its rate");
  HoldoutSpec holdout;
  holdout.mode = HoldoutSpec::Mode::None;
  if (cmd.count("--holdout")) holdout = data.holdout_spec();
  if (data.warmup) holdout.warmup = *data.warmup;
  holdout.held_start = false;  // "auto+warmup:5+held" given as --holdout
  const ModelData model_data = prepare_model_data(m, SignalScales::of(m), holdout);
  const auto dir = output.prepare("metrics.json");
  return write_and_print_comparison(dir, source, model_data, model.simulate(m.u, m.y), model.describe(),
                                    model.describe() + " on " + data.data + " (free run from the first " +
                                        std::to_string(model.lags().warmup()) + " measured samples)",
                                    mat, ComparisonInput::Record::Unknown);
}

}  // namespace hystbench::cli
