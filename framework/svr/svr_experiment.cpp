#include "framework/svr/svr_experiment.hpp"

#include <cmath>

#include "framework/core/error.hpp"
#include "framework/core/text.hpp"
#include "framework/core/parameters.hpp"
#include "framework/core/registry.hpp"
#include "framework/io/segment_runs.hpp"
#include "framework/io/data_path.hpp"
#include "framework/io/json_file.hpp"
#include "framework/report/table_format.hpp"

namespace hystbench {
namespace {

ColumnMap columns_of(const nlohmann::json& j, const std::string& where) {
  return j.contains("columns") ? ColumnMap::from_json(j["columns"], where + ".columns") : ColumnMap{};
}

// {"data": "file.csv", "segment": "label"} or "file.csv".
SvrRecord record(const nlohmann::json& j, const ColumnMap& columns, const std::filesystem::path& base_dir,
                 const std::string& where) {
  if (j.is_string()) return read_svr_record(j.get<std::string>(), "", columns, base_dir, where);
  if (!j.is_object() || !j.contains("data") || !j["data"].is_string())
    throw InputError(where + ": give {\"data\": \"file.csv\", \"segment\": \"label\"} or a file name");
  require_known_keys(j, {"data", "segment"}, where);
  return read_svr_record(j["data"].get<std::string>(), optional_text(j, "segment", "", where), columns,
                         base_dir, where);
}

void require_same_rate(const SvrRecord& r, const SvrRecord& reference, const std::string& where) {
  if (std::abs(r.data.sample_time - reference.data.sample_time) > 1e-6 * reference.data.sample_time)  // files round their times
    throw InputError(where + ": " + r.name + " is sampled every " + number_text(r.data.sample_time) +
                     " s but the stage 1 record " + reference.name + " every " +
                     number_text(reference.data.sample_time) +
                     " s; the model's lags are in samples, so resample the data to one rate");
}

void require_samples(Eigen::Index have, Eigen::Index need, const std::string& what, const std::string& where) {
  if (have < need)
    throw InputError(where + ": " + what + " has " + std::to_string(have) + " samples, fewer than the " +
                     std::to_string(need) + " the lag orders need; use a longer record or smaller lags");
}

// The search as a one-trial experiment of the harness.
Experiment search_experiment(const nlohmann::json& j, const SvrExperiment& x, const std::string& where) {
  require_known_keys(j, {"optimizer", "evaluations", "problem"}, where);
  nlohmann::json problem = j.value("problem", nlohmann::json::object());
  if (!problem.is_object()) throw InputError(where + ".problem: expected an object of svr_hyperparameters keys");
  for (const char* key : {"type", "data", "segment", "columns", "lags"})
    if (problem.contains(key))
      throw InputError(where + ".problem." + key + ": set by the experiment (stage1, columns, lags); remove it");
  const auto& s1 = x.source["stage1"];
  problem["type"] = "svr_hyperparameters";
  problem["data"] = s1.is_string() ? s1 : s1["data"];
  if (s1.is_object() && s1.contains("segment")) problem["segment"] = s1["segment"];
  if (x.source.contains("columns")) problem["columns"] = x.source["columns"];
  problem["lags"] = {{"m", x.lags.m}, {"n", x.lags.n}, {"input_rate", x.lags.input_rate}};
  const nlohmann::json optimizer = j.value("optimizer", nlohmann::json{{"name", "pso"}, {"params", {{"swarm", 20}}}});
  return Experiment::from_json({{"name", x.name + "_search"},
                                {"problem", problem},
                                {"budget", {{"evaluations", j.value("evaluations", nlohmann::json(600))}}},
                                {"trials", 1},
                                {"seed", x.source.value("seed", nlohmann::json(1))},
                                {"algorithms", nlohmann::json::array({optimizer})}},
                               where);
}

void read_tests(const nlohmann::json& j, const ColumnMap& columns, SvrExperiment& x, const std::string& where) {
  if (!j.is_array() || j.empty()) throw InputError(where + ": give a non-empty list of test records");
  for (std::size_t i = 0; i < j.size(); ++i) {
    const std::string at = where + "[" + std::to_string(i) + "]";
    x.tests.push_back(record(j[i], columns, x.base_dir, at));
    const SvrRecord& r = x.tests.back();
    require_same_rate(r, x.stage1, at);
    for (const SegmentRun& run : segment_runs(r.data.segment, r.data.size())) {
      const std::string label = run.label.empty() ? r.name : run.label;
      require_samples(run.size(), x.lags.warmup() + 2 + Eigen::Index(std::ceil(x.discard * double(run.size()))),
                      "test signal \"" + label + "\" of " + r.name, at);
      // The label names the table row and the figure files: one signal each.
      for (const SvrTestSignal& other : x.signals)
        if (table::label_key(other.label) == table::label_key(label))
          throw InputError(at + ": the test signals \"" + other.label + "\" and \"" + label +
                           "\" would share a table row and figure files; give each its own label");
      x.signals.push_back({label, i, run.begin, run.end});
    }
  }
}

SvrHyperparameters fixed_hyperparameters(const nlohmann::json& j, const std::string& where) {
  if (!j.is_object()) throw InputError(where + ": give {\"epsilon\": .., \"C\": .., \"sigma\": ..}");
  require_known_keys(j, {"epsilon", "C", "sigma"}, where);
  for (const char* key : {"epsilon", "C", "sigma"})
    if (!j.contains(key) || !j[key].is_number()) throw InputError(where + "." + key + ": expected a number");
  const SvrHyperparameters h{j["epsilon"].get<double>(), j["C"].get<double>(), j["sigma"].get<double>()};
  SvrRegressor::check(h, where);
  return h;
}

SvrCoupling read_coupling(const std::string& name, const std::string& where) {
  if (name == "free_run") return SvrCoupling::FreeRun;
  if (name == "one_step") return SvrCoupling::OneStep;
  throw InputError(where + ".coupling: \"" + name + "\" is not a coupling; give \"free_run\" (stage 2 "
                   "fitted on stage 1's free run, the default) or \"one_step\" (on its one-step prediction)");
}

}  // namespace

SvrExperiment SvrExperiment::load(const std::filesystem::path& file) {
  return from_json(read_json_file(file, "experiment file"), file.parent_path(), file.string());
}

SvrExperiment SvrExperiment::from_json(const nlohmann::json& j, const std::filesystem::path& base_dir,
                                       const std::string& where) {
  if (!j.is_object()) throw InputError(where + ": the experiment must be a JSON object");
  require_known_keys(j, {"name", "description", "columns", "stage1", "stage2", "tests", "lags", "search", "arx",
                         "greybox", "discard", "seed", "units", "hyperparameters", "train_rows", "records",
                         "coupling"},
                     where);
  SvrExperiment x;
  x.source = j;
  x.base_dir = base_dir;
  x.name = optional_text(j, "name", "svr", where);
  x.description = optional_text(j, "description", "", where);
  const nlohmann::json lags = j.value("lags", nlohmann::json::object());
  require_known_keys(lags, {"m", "n", "input_rate"}, where + ".lags");
  x.lags = {int(optional_number(lags, "m", 4, 0, 50, where + ".lags")),
            int(optional_number(lags, "n", 4, 0, 50, where + ".lags")),
            optional_flag(lags, "input_rate", false, where + ".lags")};
  x.coupling = read_coupling(optional_text(j, "coupling", "free_run", where), where);
  const nlohmann::json arx = j.value("arx", nlohmann::json::object());
  require_known_keys(arx, {"p_max", "q_max"}, where + ".arx");
  x.p_max = int(optional_number(arx, "p_max", 5, 1, 20, where + ".arx"));
  x.q_max = int(optional_number(arx, "q_max", 5, 1, 20, where + ".arx"));
  x.discard = optional_number(j, "discard", 0.2, 0.0, 0.9, where);
  const nlohmann::json units = j.value("units", nlohmann::json::object());
  require_known_keys(units, {"u", "y"}, where + ".units");
  x.u_unit = optional_text(units, "u", "", where + ".units");
  x.y_unit = optional_text(units, "y", "", where + ".units");
  const ColumnMap columns = columns_of(j, where);
  for (const char* key : {"stage1", "tests"})
    if (!j.contains(key)) throw InputError(where + ": missing key \"" + key + "\"");
  x.stage1 = record(j["stage1"], columns, base_dir, where + ".stage1");
  x.train_rows = long(optional_number(j, "train_rows", 0, 0, 1e9, where));
  if (j.contains("stage2")) {
    x.stage2 = record(j["stage2"], columns, base_dir, where + ".stage2");
    require_same_rate(*x.stage2, x.stage1, where + ".stage2");
    require_samples(x.stage2->data.size(), x.lags.warmup() + 4 * (x.p_max + x.q_max),
                    "the stage 2 record " + x.stage2->name, where + ".stage2");
  }
  read_tests(j["tests"], columns, x, where + ".tests");
  if (j.contains("hyperparameters") && j.contains("search"))
    throw InputError(where + ": give either \"hyperparameters\" (fixed) or \"search\", not both");
  if (j.contains("hyperparameters")) x.fixed = fixed_hyperparameters(j["hyperparameters"], where + ".hyperparameters");
  x.search = search_experiment(j.value("search", nlohmann::json::object()), x, where + ".search");
  x.search.base_dir = base_dir;
  try {
    x.search_problem = make_problem(x.search.problem, base_dir);  // reads and checks stage 1
  } catch (const InputError& e) {  // its messages say "problem.KEY"
    throw InputError(where + ".search." + e.what());
  }
  if (j.contains("greybox")) {
    if (!j["greybox"].is_string()) throw InputError(where + ".greybox: give the path of a fit.json");
    x.greybox_path = j["greybox"].get<std::string>();
    x.greybox = FitRecord::read(resolve_data_path(x.greybox_path, base_dir, where + ".greybox"));
  }
  return x;
}

}  // namespace hystbench
