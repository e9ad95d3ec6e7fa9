#pragma once
// Options shared by fit, compare, diagnose and discover: which data, which
// columns and units, what is held out, how to fit, where to write.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <optional>
#include <string>

#include "framework/discovery/data_source.hpp"
#include "framework/discovery/diagnosis.hpp"
#include "framework/discovery/fit_record.hpp"
#include "framework/discovery/model_fit.hpp"
#include "framework/model/input_hold.hpp"

namespace hystbench::cli {

struct DataOptions {
  std::string data, columns, delimiter, input_unit, output_unit, holdout = "auto";
  std::optional<long> warmup;                 // --warmup; unset: 0, or a fit's own
  std::optional<std::string> initial_state;  // --initial-state rest|held; unset: rest, or a fit's own
  DataSource source() const;
  HoldoutSpec holdout_spec() const;
  // The warm-up and initial state of `spec`: as given, else those of the
  // fit (`fit`) when `spec` has none of its own.
  void take_start(HoldoutSpec& spec, const HoldoutSpec& fit) const;
};
// --data (required), --columns, --delimiter, --input-unit, --output-unit,
// --warmup, --initial-state; --holdout when `with_holdout`.
void add_data_options(CLI::App* cmd, DataOptions& o, bool with_holdout = true);

// The measurement a fit record is used on: its columns and units unless
// given, its fit's scales, and the hold-out: --holdout when given, else the
// fit's own on the data it was fitted to, else `elsewhere`. The warm-up is
// --warmup when given, else the fit's own on any record: a test record is
// scored after the same warm-up as the fit.
ModelData data_for_fit(const DataOptions& o, const FitRecord& fit, DataSource& source, bool holdout_given,
                       HoldoutSpec::Mode elsewhere);

// Whether `source` is the file the fit was made on (false when that file is
// gone or was named by a path that no longer leads to it).
bool fitted_on(const FitRecord& fit, const DataSource& source);

struct FitCliOptions {
  FitOptions fit;  // the library's defaults are the command line's
  std::string optimizer_params = "{}";
  int substeps = 0;
  // fit.json records a hold other than the spline, so compare and diagnose
  // --fit simulate the model as it was fitted.
  InputHold input_hold = InputHold::Spline;
  // Validated (bad optimizer, parameters or local method -> InputError).
  FitOptions fit_options() const;
};
void add_fit_options(CLI::App* cmd, FitCliOptions& o);

// What fit and diagnose fit: the fit `start` with its scales, warm-up,
// initial state, sub-steps and input hold (each unless `cmd` gives it),
// else the model `list` on the measurement's own scales.
struct FitSubject {
  Model model;
  HoldoutSpec holdout;
  ModelData data;
};
FitSubject fit_subject(const DataOptions& data, const FitCliOptions& fit, const CLI::App& cmd, const Measurement& m,
                       const std::optional<FitRecord>& start, const std::string& list);

// The significance rule of diagnose and discover, and which effects to try.
struct DiagnoseCliOptions {
  std::string candidates;  // comma-separated; empty = the whole catalog
  double bic_threshold = -10.0, heldout_gain = 0.01;
  int candidate_restarts = 1;
  DiagnoseOptions diagnose_options(FitOptions fit, const DataSource& source) const;
};
void add_diagnose_options(CLI::App* cmd, DiagnoseCliOptions& o);

// --out DIR and --force.
struct OutputOptions {
  std::string out;
  bool force = false;
  // Creates the folder; refuses to overwrite `marker` there without --force.
  std::filesystem::path prepare(const std::string& marker) const;
};
void add_output_options(CLI::App* cmd, OutputOptions& o);

}  // namespace hystbench::cli
