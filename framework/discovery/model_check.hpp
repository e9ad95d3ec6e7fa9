#pragma once
// What a reader must know before trusting a fitted model's parameters:
// each value with its standard error (parameter_uncertainty.hpp), the
// parameters that sit on a bound of the search box, the effects that do
// nothing within noise (every parameter within two standard errors of its
// neutral value: the effect could be removed without changing the fit
// measurably), and the pair of parameters that trade against each other most.
#include "framework/core/eigen.hpp"
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/model/model.hpp"

namespace hystbench {

struct FittedParameter {
  std::string name, unit;
  double value = 0.0, sd = 0.0;  // physical; sd +inf when undetermined, NaN when unknown
  double normalised = 0.0;
  bool at_bound = false;
  // A parameter counted in samples is also given in seconds (NaN otherwise).
  double seconds = 0.0, sd_seconds = 0.0;
};

struct EffectCheck {
  std::string effect;
  bool neutral = false;  // every parameter within 2 sd (or 1e-6 of its range) of neutral
  std::vector<std::string> at_bound;
  // What the fitted effect is where its name would mislead
  // (EffectInfo::reading): "As fitted, feedback_hysteresis has no loop ...: a
  // hardening spring, not hysteresis." Empty when the name says it.
  std::string reading = {};
};

struct ModelCheck {
  std::vector<FittedParameter> parameters;
  std::vector<EffectCheck> effects;
  std::vector<std::string> shared_modes;  // dynamics effects resonating together (resonance.hpp)
  std::string correlated_a, correlated_b;  // the most correlated pair ("" when none)
  double correlation = 0.0;

  bool neutral(const std::string& effect) const;
  // The effect's reading, "" when it has none.
  std::string reading(const std::string& effect) const;
  // Plain sentences: what effects are as fitted, neutral effects, parameters
  // on bounds, a strong trade-off.
  std::vector<std::string> warnings() const;
  nlohmann::json to_json() const;
};

ModelCheck check_model(const Model& model, const Eigen::VectorXd& x, const ModelData& data,
                       const std::string& u_unit, const std::string& y_unit);

// The parameters of `model` at `x` that sit on a bound of their search
// range (and not at their neutral value there), by name: what check_model
// flags, without the Jacobian.
std::vector<std::string> parameters_on_bound(const Model& model, const Eigen::VectorXd& x);

}  // namespace hystbench
