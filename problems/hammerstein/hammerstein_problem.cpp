#include "problems/hammerstein/hammerstein_problem.hpp"

#include <fstream>
#include <tuple>

#include "framework/core/error.hpp"
#include "framework/core/registry.hpp"
#include "framework/io/data_path.hpp"
#include "framework/io/truth_file.hpp"
#include "problems/hammerstein/batched_sse.hpp"

namespace hystbench {
namespace {

// Reads {"name": [lo, hi], ...} on top of the defaults.
Bounds apply_bound_overrides(Bounds bounds, const nlohmann::json& overrides) {
  require_known_keys(overrides, bounds.names, "problem.bounds");
  for (int j = 0; j < bounds.dimension(); ++j) {
    const auto it = overrides.find(bounds.names[j]);
    if (it == overrides.end()) continue;
    std::tie(bounds.lower[j], bounds.upper[j]) = read_range(*it, "problem.bounds." + bounds.names[j]);
  }
  return bounds;
}

HammersteinProblem::Units read_units(const nlohmann::json& j, const std::string& where) {
  require_known_keys(j, {"t", "u", "y"}, where);
  for (const char* key : {"u", "y"})
    if (j.contains(key) && !j[key].is_string())
      throw InputError(where + "." + key + ": expected a unit name such as \"V\" or \"µm\"");
  return {j.value("u", ""), j.value("y", "")};
}

std::unique_ptr<Problem> create(const Params& p, const std::filesystem::path& base_dir) {
  const auto path = resolve_data_path(p.text("data"), base_dir, "problem.data");
  const ColumnMap columns =
      p.is_auto("columns") ? ColumnMap{} : ColumnMap::from_json(p.value("columns"), "problem.columns");
  Bounds bounds = HammersteinProblem::default_bounds();
  if (!p.is_auto("bounds")) bounds = apply_bound_overrides(bounds, p.value("bounds"));
  const nlohmann::json truth = read_truth(path);
  const auto units = !p.is_auto("units") ? read_units(p.value("units"), "problem.units")
                                         : read_units(truth.value("units", nlohmann::json::object()),
                                                      path.string() + " truth units");
  std::optional<double> noise_floor;
  if (truth.contains("noise_floor_sse") && truth["noise_floor_sse"].is_number())
    noise_floor = truth["noise_floor_sse"].get<double>();
  return std::make_unique<HammersteinProblem>(read_measurement(path, columns),
                                              bouc_wen_form_from_string(p.text("bouc_wen_form")),
                                              bounds, units, noise_floor);
}

}  // namespace

HammersteinProblem::HammersteinProblem(Measurement data, BoucWenForm form, Bounds bounds, Units units,
                                       std::optional<double> noise_floor)
    : data_(std::move(data)),
      form_(form),
      bounds_(std::move(bounds)),
      noise_floor_(noise_floor),
      units_(std::move(units)) {}

ProblemInfo HammersteinProblem::info() {
  return {"hammerstein",
          "13-parameter Hammerstein MFC model (Bouc-Wen, asymmetric static part, "
          "mass-spring-damper, ARX); fitness = SSE over the record",
          {ParamSpec::text("data", nullptr, "the measurement CSV file").require(),
           ParamSpec::object("columns", "column names of t, u, y in the CSV"),
           ParamSpec::choice("bouc_wen_form", "increment", {"increment", "paper"},
                             "discretisation of the Bouc-Wen equation"),
           ParamSpec::object("bounds", "{\"name\": [lower, upper]} over the default box"),
           ParamSpec::object("units", "{\"u\": \"V\", \"y\": \"µm\"} for tables and figures")},
          create};
}

Bounds HammersteinProblem::default_bounds() {
  const auto& n = HammersteinParams::names();
  Bounds b;
  b.names.assign(n.begin(), n.end());
  b.lower.resize(HammersteinParams::kCount);
  b.upper.resize(HammersteinParams::kCount);
  //        alpha beta  gamma  L   d1   d2     M     D     K    a   b   c   d
  b.lower << 0.0, 0.0, -0.01, 0.0, 0.0, -1e-4, 1e-6, 1e-5, 0.1, -1, -1, -2, -1;
  b.upper << 1.0, 0.01, 0.01, 1.0, 0.5, 1e-4, 1e-4, 1e-2, 10, 1, 1, 2, 1;
  return b;
}

std::string HammersteinProblem::name() const {
  return "hammerstein(" + std::filesystem::path(data_.source).filename().string() + ")";
}

void HammersteinProblem::evaluate(const Eigen::Ref<const Eigen::MatrixXd>& X,
                                  Eigen::Ref<Eigen::VectorXd> f) const {
  evaluate_with(X, f, {});
}

void HammersteinProblem::evaluate_with(const Eigen::Ref<const Eigen::MatrixXd>& X,
                                       Eigen::Ref<Eigen::VectorXd> f,
                                       const EvaluationOptions& options) const {
  hammerstein_sse_batched(X, data_.u, data_.y, data_.sample_time, form_, f, options);
}

Eigen::VectorXd HammersteinProblem::simulate(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  return simulate_hammerstein(HammersteinParams::from_vector(x), data_.u, data_.sample_time, form_);
}

void HammersteinProblem::residuals(const Eigen::Ref<const Eigen::VectorXd>& x,
                                   Eigen::Ref<Eigen::VectorXd> r) const {
  r = data_.y - simulate(x);
}

nlohmann::json HammersteinProblem::describe() const {
  nlohmann::json j = {{"name", name()},
                      {"type", "hammerstein"},
                      {"fitness", "SSE"},
                      {"data", data_.source},
                      {"samples", data_.size()},
                      {"sample_time", data_.sample_time},
                      {"bouc_wen_form", to_string(form_)},
                      {"parameters", bounds_.names},
                      {"lower", std::vector<double>(bounds_.lower.begin(), bounds_.lower.end())},
                      {"upper", std::vector<double>(bounds_.upper.begin(), bounds_.upper.end())}};
  if (noise_floor_) j["noise_floor_sse"] = *noise_floor_;
  return j;
}

}  // namespace hystbench

HYSTBENCH_PROBLEM(hystbench::HammersteinProblem)
