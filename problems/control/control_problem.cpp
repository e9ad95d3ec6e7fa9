#include "problems/control/control_problem.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "framework/control/control_metrics.hpp"
#include "framework/control/controller.hpp"
#include "framework/control/uncontrolled.hpp"
#include "framework/core/error.hpp"
#include "framework/io/data_path.hpp"

namespace hystbench {
namespace {

ControlExperiment load_experiment(const Params& p, const std::filesystem::path& base_dir) {
  const auto path = resolve_data_path(p.text("experiment"), base_dir, "problem.experiment");
  ControlExperiment x = ControlExperiment::load(path);
  if (!p.is_auto("duration_s")) {
    if (!(p.real("duration_s") >= x.windows.steady_s))
      throw InputError("problem.duration_s: give a number of seconds above the steady window (" +
                       std::to_string(x.windows.steady_s) + " s)");
    x.loop.duration_s = p.real("duration_s");
  }
  return x;
}

}  // namespace

ProblemInfo ControlProblem::info() {
  return {"control",
          "tuning of a vibration controller's constants: one closed-loop run per candidate, "
          "fitness = steady error ratio + weight x convergence time",
          {ParamSpec::text("experiment", nullptr,
                           "the control experiment file (plant, actuator, disturbance, secondary "
                           "path) whose loop is tuned")
               .require(),
           ParamSpec::text("controller", nullptr, "the controller to tune (hystbench list controllers)")
               .require(),
           ParamSpec::object("params", "the controller's fixed constants"),
           ParamSpec::array("tune",
                            "the constants to tune, e.g. [{\"param\": \"mu\", \"lower\": 0.001, "
                            "\"upper\": 0.03, \"scale\": \"log\"}]")
               .require(),
           ParamSpec::real("convergence_weight", 1e-3, 0.0, 1e12,
                           "weight of the convergence time (s) against the error ratio"),
           ParamSpec::integer("noise_seed", 1, 0, 9007199254740992.0, "seed of the loop's noise"),
           ParamSpec::real("duration_s", nullptr, 0.0, 1e9,
                           "length of each closed-loop run; auto = the experiment's")},
          [](const Params& p, const std::filesystem::path& base_dir) {
            return std::unique_ptr<Problem>(new ControlProblem(p, base_dir));
          }};
}

ControlProblem::ControlProblem(const Params& p, const std::filesystem::path& base_dir)
    : experiment_(load_experiment(p, base_dir)), setup_(build_control_setup(experiment_)) {
  controller_ = p.text("controller");
  const ControllerInfo& info = ControllerRegistry::instance().find(controller_, "problem.controller");
  fixed_ = p.is_auto("params") ? nlohmann::json::object() : p.value("params");
  const nlohmann::json& tune = p.value("tune");
  if (tune.empty())
    throw InputError("problem.tune: give at least one constant to tune, e.g. [{\"param\": \"mu\", "
                     "\"lower\": 0.001, \"upper\": 0.03, \"scale\": \"log\"}]");
  const int n = int(tune.size());
  bounds_.lower.resize(n);
  bounds_.upper.resize(n);
  for (int i = 0; i < n; ++i) {
    const auto& t = tune[i];
    const std::string at = "problem.tune[" + std::to_string(i) + "]";
    require_known_keys(t, {"param", "lower", "upper", "scale"}, at);
    const std::string scale = optional_text(t, "scale", "linear", at);
    if (scale != "linear" && scale != "log") throw InputError(at + ".scale: give \"linear\" or \"log\"");
    Tuned tuned{optional_text(t, "param", "", at), scale == "log"};
    const auto spec_of = std::find_if(info.params.begin(), info.params.end(),
                                      [&](const ParamSpec& p) { return p.name == tuned.param; });
    if (spec_of == info.params.end() || spec_of->type != ParamSpec::Type::Real)
      throw InputError(at + ".param: '" + tuned.param + "' is not a real-valued parameter of " +
                       controller_ + " (hystbench list controllers); integers and choices cannot be tuned");
    const double lo = optional_number(t, "lower", NAN, -1e300, 1e300, at);
    const double hi = optional_number(t, "upper", NAN, -1e300, 1e300, at);
    if (!(lo < hi) || (tuned.log && !(lo > 0.0)))
      throw InputError(at + ": give lower < upper" + std::string(tuned.log ? ", both above 0 for scale log" : ""));
    // Both ends must be valid values of the controller's parameter.
    for (double v : {lo, hi}) {
      nlohmann::json params = fixed_;
      params[tuned.param] = v;
      validate_params(info.params, params, at);
    }
    bounds_.lower[i] = tuned.log ? std::log10(lo) : lo;
    bounds_.upper[i] = tuned.log ? std::log10(hi) : hi;
    bounds_.names.push_back(tuned.log ? "log10(" + tuned.param + ")" : tuned.param);
    tuned_.push_back(tuned);
  }
  convergence_weight_ = p.real("convergence_weight");
  noise_seed_ = std::uint64_t(p.real("noise_seed"));
  uncontrolled_ = run_uncontrolled(setup_.paths, setup_.loop, noise_seed_);
}

std::string ControlProblem::name() const { return "control(" + experiment_.name + ", " + controller_ + ")"; }

nlohmann::json ControlProblem::params_of(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  nlohmann::json p = fixed_;
  for (std::size_t i = 0; i < tuned_.size(); ++i)
    p[tuned_[i].param] = tuned_[i].log ? std::pow(10.0, x[Eigen::Index(i)]) : x[Eigen::Index(i)];
  return p;
}

double ControlProblem::fitness(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  const ControllerInfo& info = ControllerRegistry::instance().find(controller_, "problem.controller");
  std::unique_ptr<Controller> c;
  try {
    c = info.create(validate_params(info.params, params_of(x), "problem"));
  } catch (const InputError&) {
    return std::numeric_limits<double>::infinity();  // e.g. mu_min above mu_max
  }
  const LoopTrace t = run_loop(setup_.paths, *setup_.estimates[0].stream, *c, setup_.loop, noise_seed_);
  if (t.diverged()) return std::numeric_limits<double>::infinity();
  const SuppressionMetrics m = suppression_metrics(t.true_error, uncontrolled_.true_error, experiment_.windows);
  const double convergence = std::isnan(m.convergence_s) ? experiment_.loop.duration_s : m.convergence_s;
  return std::pow(10.0, -m.attenuation_db / 20.0) + convergence_weight_ * convergence;
}

void ControlProblem::evaluate(const Eigen::Ref<const Eigen::MatrixXd>& X, Eigen::Ref<Eigen::VectorXd> f) const {
  for (Eigen::Index i = 0; i < X.cols(); ++i) f[i] = fitness(X.col(i));
}

nlohmann::json ControlProblem::describe() const {
  return {{"name", name()},
          {"fitness", "error ratio + weight x convergence time"},
          {"experiment", experiment_.name},
          {"controller", controller_},
          {"fixed_params", fixed_},
          {"convergence_weight", convergence_weight_},
          {"noise_seed", noise_seed_},
          {"duration_s", experiment_.loop.duration_s}};
}

}  // namespace hystbench

HYSTBENCH_PROBLEM(hystbench::ControlProblem)
