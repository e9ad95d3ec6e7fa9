#include "framework/cli/svr_comparison.hpp"

#include <cmath>
#include <iostream>

#include "framework/cli/fit_summary.hpp"
#include "framework/core/error.hpp"
#include "framework/core/text.hpp"
#include "framework/discovery/comparison_report.hpp"
#include "framework/discovery/model_comparison.hpp"
#include "framework/svr/svr_model.hpp"

namespace hystbench::cli {

Comparison compare_svr_model(const nlohmann::json& file, const std::string& path, const DataOptions& data,
                             const OutputOptions& output, const CLI::App& cmd) {
  const SvrHammerstein model = SvrHammerstein::from_json(file, path);
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
  const ModelData model_data = prepare_model_data(m, SignalScales::of(m), holdout);
  const auto dir = output.prepare("metrics.json");
  const auto input = comparison_input(model_data, model.simulate(m.u, m.y), source.u_unit, source.y_unit);
  const Comparison metrics = compare_signals(input);
  const auto files = write_comparison(dir, input, metrics, "Model " + model.describe() + " against " + source.file_name(),
                                      model.describe());
  std::cout << "model " << model.describe() << " on " << data.data << " (free run from the first "
            << model.lags().warmup() << " measured samples)\n";
  print_comparison_headline(metrics, source.y_unit);
  std::cout << "wrote " << files.size() << " files in " << dir.string() << " (see report.md)\n";
  return metrics;
}

}  // namespace hystbench::cli
