#include "framework/discovery/model_check.hpp"

#include <cmath>

#include "framework/core/text.hpp"
#include "framework/discovery/error_metrics.hpp"
#include "framework/discovery/parameter_uncertainty.hpp"
#include "framework/discovery/resonance.hpp"
#include "framework/io/json_number.hpp"
#include "framework/model/effect.hpp"

namespace hystbench {
namespace {

constexpr double kNeutralSd = 2.0;         // "within noise" of the neutral value
constexpr double kBoundTolerance = 1e-6;   // of the parameter's range
constexpr double kStrongCorrelation = 0.95;


bool near_neutral(const EffectParam& p, double x, double sd) {
  const double gap = std::abs(x - p.neutral);
  return gap <= kBoundTolerance * (p.upper - p.lower) || (std::isfinite(sd) && gap <= kNeutralSd * sd);
}

bool on_bound(const EffectParam& p, double x) {
  const double tol = kBoundTolerance * (p.upper - p.lower);
  return !p.shape && p.upper > p.lower && (x <= p.lower + tol || x >= p.upper - tol) && !near_neutral(p, x, 0.0);
}

std::vector<FittedParameter> fitted_parameters(const Model& model, const Eigen::VectorXd& x,
                                               const ModelData& data, const ParameterUncertainty& u,
                                               const nlohmann::json& units) {
  const auto names = model.parameter_names();
  const nlohmann::json values = model.physical_values(x, data.scales);
  std::vector<FittedParameter> out;
  for (int i = 0; i < model.dimension(); ++i) {
    const EffectParam& p = model.parameter(i);
    FittedParameter f{names[i], units.value(names[i], std::string())};
    f.value = values[names[i]].get<double>();
    f.sd = u.sd[i] * std::abs(physical_factor(p, data.scales));
    f.normalised = x[i];
    f.at_bound = on_bound(p, x[i]);
    const bool samples = p.unit == "samples";
    f.seconds = samples ? f.value * data.sample_time : std::nan("");
    f.sd_seconds = samples ? f.sd * data.sample_time : std::nan("");
    out.push_back(f);
  }
  return out;
}

// "As fitted, <effect> <what its reading says>.", or "".
std::string effect_reading(const std::string& effect, const std::vector<double>& p) {
  const auto& info = EffectRegistry::instance().find(effect, "effect");
  if (!info.reading) return "";
  const std::string r = info.reading(p);
  return r.empty() ? "" : "As fitted, " + effect + " " + r + ".";
}

}  // namespace

bool ModelCheck::neutral(const std::string& effect) const {
  for (const auto& e : effects)
    if (e.effect == effect) return e.neutral;
  return false;
}

std::string ModelCheck::reading(const std::string& effect) const {
  for (const auto& e : effects)
    if (e.effect == effect) return e.reading;
  return "";
}

std::vector<std::string> ModelCheck::warnings() const {
  std::vector<std::string> out;
  for (const auto& e : effects) {
    if (!e.reading.empty()) out.push_back(e.reading);
    if (e.neutral)
      out.push_back(e.effect + " does nothing within noise: every parameter lies within " +
                    format_number("%.0f", kNeutralSd) + " standard errors of its neutral value.");
    for (const auto& name : e.at_bound)
      out.push_back(name + " sits on a bound of its search range: the effect may be standing in "
                           "for something else, or the range is too narrow.");
  }
  for (const auto& s : shared_modes) out.push_back(s + ".");
  if (std::abs(correlation) >= kStrongCorrelation)
    out.push_back(correlated_a + " and " + correlated_b + " trade against each other (correlation " +
                  format_number("%.3f", correlation) + "): the data hardly tell them apart.");
  return out;
}

ModelCheck check_model(const Model& model, const Eigen::VectorXd& x, const ModelData& data,
                       const std::string& u_unit, const std::string& y_unit) {
  const ParameterUncertainty u = parameter_uncertainty(model, x, data);
  ModelCheck c;
  c.parameters = fitted_parameters(model, x, data, u, model.physical_units(u_unit, y_unit));
  for (const auto& effect : model.effects()) {
    EffectCheck e{effect, true, {}};
    std::vector<double> p;
    for (int i : model.parameters_of(effect)) {
      const EffectParam& param = model.parameter(i);
      if (!param.shape) e.neutral = e.neutral && u.available && near_neutral(param, x[i], u.sd[i]);
      if (c.parameters[i].at_bound) e.at_bound.push_back(c.parameters[i].name);
      p.push_back(x[i]);
    }
    e.reading = effect_reading(effect, p);
    c.effects.push_back(e);
    if (auto shared = shared_resonance(model, x, data.sample_time, effect); !shared.empty())
      c.shared_modes.push_back(std::move(shared));
  }
  const auto [pair, value] = u.most_correlated();
  if (pair.first >= 0) {
    c.correlated_a = c.parameters[pair.first].name;
    c.correlated_b = c.parameters[pair.second].name;
    c.correlation = value;
  }
  return c;
}

nlohmann::json ModelCheck::to_json() const {
  nlohmann::json params = nlohmann::json::array();
  for (const auto& p : parameters) {
    nlohmann::json j = {{"name", p.name},       {"value", p.value},
                        {"sd", std::isinf(p.sd) ? nlohmann::json("undetermined") : number_or_null(p.sd)},
                        {"unit", p.unit},       {"at_bound", p.at_bound}};
    if (std::isfinite(p.seconds)) j["seconds"] = p.seconds, j["sd_seconds"] = number_or_null(p.sd_seconds);
    params.push_back(j);
  }
  nlohmann::json effs = nlohmann::json::array();
  for (const auto& e : effects)
    effs.push_back({{"effect", e.effect}, {"neutral", e.neutral}, {"at_bound", e.at_bound}, {"reading", e.reading}});
  nlohmann::json j = {{"parameters", params}, {"effects", effs}, {"warnings", warnings()}};
  if (!correlated_a.empty())
    j["most_correlated"] = {{"a", correlated_a}, {"b", correlated_b}, {"correlation", correlation}};
  return j;
}

std::vector<std::string> parameters_on_bound(const Model& model, const Eigen::VectorXd& x) {
  const auto names = model.parameter_names();
  std::vector<std::string> out;
  for (int i = 0; i < model.dimension(); ++i)
    if (on_bound(model.parameter(i), x[i])) out.push_back(names[i]);
  return out;
}

}  // namespace hystbench
