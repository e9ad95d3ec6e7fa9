#pragma once
// An SVR experiment file (docs/svr.md#experiment-file): the records stage 1
// and stage 2 train on, the test records (every segment of a test file is
// one test signal, one row of the table), the lag orders, the
// hyperparameter search (any optimizer plugin on the svr_hyperparameters
// problem), the AIC grid, and optionally a grey-box fit.json scored on the
// same tests.
//
//   {"name": "svr_piezo",
//    "stage1": {"data": "train.csv", "segment": "train 1 Hz"},
//    "stage2": {"data": "train.csv", "segment": "scan 1-100 Hz"},
//    "tests": [{"data": "test.csv"}],
//    "lags": {"m": 4, "n": 4},
//    "search": {"optimizer": {"name": "pso", "params": {"swarm": 20}}, "evaluations": 600,
//               "problem": {"fitness": "blocked_cv", "max_rows": 2000}},
//    "arx": {"p_max": 5, "q_max": 5},
//    "greybox": "greybox/fit.json",
//    "discard": 0.2, "seed": 1, "units": {"u": "V", "y": "µm"}}
//
// Without "stage2" the model is stage 1 alone (a NARX model for data that
// are not a 1 Hz record and a scan). "train_rows" caps the rows the final
// stage 1 trains on (libsvm's cost grows with the square of the rows).
// "hyperparameters": {"epsilon": 0.001, "C": 10, "sigma": 1} instead of
// "search" skips the tuning. "lags" may add the input's rate to stage 1's
// regressors ("input_rate": true), and "coupling": "one_step" fits stage 2
// on stage 1's one-step prediction instead of its free run (ablations).
//
// Everything is read and checked on load (records, sampling rates, lengths,
// the search problem), so a bad file stops the command before any output.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "framework/core/problem.hpp"
#include "framework/discovery/fit_record.hpp"
#include "framework/harness/experiment.hpp"
#include "framework/svr/svr_model.hpp"
#include "framework/svr/svr_record.hpp"

namespace hystbench {

// One test signal: a contiguous segment of a test record.
struct SvrTestSignal {
  std::string label;  // the segment label, e.g. "20 Hz"; the file name when unlabelled
  std::size_t record = 0;  // index into SvrExperiment::tests
  Eigen::Index begin = 0, end = 0;
};

struct SvrExperiment {
  std::string name, description;
  std::string u_unit, y_unit;  // for table heads and figure axes
  SvrRecord stage1;
  std::optional<SvrRecord> stage2;  // none: stage 1 alone is the model
  long train_rows = 0;              // stage 1's final training rows (0: all), uniformly decimated
  std::vector<SvrRecord> tests;
  std::vector<SvrTestSignal> signals;
  SvrLags lags;                               // "lags": {"m", "n", "input_rate"}
  SvrCoupling coupling = SvrCoupling::FreeRun;  // "coupling": "free_run" or "one_step"
  // Either fixed hyperparameters ("hyperparameters": {"epsilon", "C",
  // "sigma"}) or a search: one trial of one optimizer on the
  // svr_hyperparameters problem.
  std::optional<SvrHyperparameters> fixed;
  Experiment search;
  std::shared_ptr<const Problem> search_problem;
  int p_max = 5, q_max = 5;
  std::optional<FitRecord> greybox;
  std::string greybox_path;
  double discard = 0.2;  // leading fraction of each test signal not scored (warm-up)
  std::filesystem::path base_dir;
  nlohmann::json source;  // the file as read

  // Throws InputError naming the file and the key.
  static SvrExperiment load(const std::filesystem::path& file);
  static SvrExperiment from_json(const nlohmann::json& j, const std::filesystem::path& base_dir,
                                 const std::string& where);
};

}  // namespace hystbench
