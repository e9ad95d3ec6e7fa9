#pragma once
// A discovery model: a static gain and an ordered list of effects, with one
// flat parameter vector "gain", "<effect>.<param>", ... in normalised units.
#include "framework/core/eigen.hpp"
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

#include "framework/core/problem.hpp"
#include "framework/model/effect.hpp"
#include "framework/model/model_data.hpp"

namespace hystbench {

class Model {
 public:
  // `effects` in any order: they are kept in chain order (by stage, then as
  // given). Throws InputError for an unknown or repeated name, naming the
  // catalog.
  explicit Model(const std::vector<std::string>& effects, const std::string& where = "model");
  // "hysteresis,asymmetry,msd,arx"; "none" is the gain alone. Throws
  // InputError naming `where` for an empty list.
  static Model parse(const std::string& list, const std::string& where = "--model");

  const std::vector<std::string>& effects() const { return names_; }
  bool has(const std::string& effect) const;
  // Comma-separated effect list ("none" for the gain alone).
  std::string text() const;

  int dimension() const { return static_cast<int>(params_.size()); }
  // "gain", "hysteresis.A", ...
  std::vector<std::string> parameter_names() const;
  const EffectParam& parameter(int i) const { return params_[i]; }
  // Normalised bounds, named by parameter_names().
  Bounds bounds() const;
  // Gain 1, every effect at its neutral value.
  Eigen::VectorXd neutral() const;
  // Indices of the parameters belonging to `effect`.
  std::vector<int> parameters_of(const std::string& effect) const;

  // `effect` added after the last effect of its stage, or in place of the
  // effect it extends.
  Model with(const std::string& effect) const;
  Model without(const std::string& effect) const;
  // A parameter vector of this model that reproduces `x_from` of `from`:
  // parameters of the same effect and name are copied (an extending effect
  // takes those of the effect it replaces), the rest stay neutral.
  Eigen::VectorXd carry_over(const Model& from, const Eigen::Ref<const Eigen::VectorXd>& x_from) const;

  // Integration sub-steps per sample for ODE effects (0 = their default).
  void set_substeps(int substeps) { substeps_ = substeps; }
  int substeps() const { return substeps_; }
  // How ODE effects reconstruct the input between samples in simulate()
  // (input_hold.hpp; the spline unless set).
  void set_input_hold(InputHold hold) { input_hold_ = hold; }
  InputHold input_hold() const { return input_hold_; }

  // The effects in chain order, each with the index of its first parameter
  // (StreamingModel runs them one sample at a time).
  struct ChainEntry {
    const EffectInfo* info;
    std::shared_ptr<const Effect> effect;
    int offset;  // index of its first parameter
  };
  const std::vector<ChainEntry>& chain() const { return entries_; }

  // Normalised model output for `x`. Returns false when the parameters make
  // the model unstable; `y` is then unspecified.
  bool simulate(const Eigen::Ref<const Eigen::VectorXd>& x, const ModelData& data,
                Eigen::VectorXd& y) const;

  // Where a term can be added to the chain (a proposed term,
  // docs/discovery.md#proposing-a-missing-term): to the drive v (after the
  // input effects, before the gain: the nonlinearity sees it), to the
  // dynamics' input w, or to the output.
  enum class Entry { Drive, Dynamics, Output };
  // The inner signals of one simulation: the drive v, the dynamics' input
  // w, the output of the first dynamics effect (the resonance a force
  // inside the dynamics acts on; w when there is none) and the dynamics'
  // output x (before the output effects).
  struct ChainSignals {
    Eigen::VectorXd v, w, resonance, x;
  };
  // simulate() with `added` (when not null) added to the signal at `entry`,
  // and the inner signals written to `signals` (when not null).
  bool simulate_probed(const Eigen::Ref<const Eigen::VectorXd>& x, const ModelData& data, Eigen::VectorXd& y,
                       Entry entry, const Eigen::VectorXd* added, ChainSignals* signals) const;

  // True when every effect has a batched form: simulate_lanes() works.
  bool has_lanes() const;
  // Receives the output of simulate_lanes() a chunk at a time: samples
  // [begin, begin + y.size()).
  using LaneSink = std::function<void(Eigen::Index begin, std::span<const LaneVector> y)>;
  // simulate() for the kEffectLanes candidates in the columns of X at once,
  // every effect run on a chunk of samples before the next chunk so that the
  // block's signals stay in cache: lane l of the output is exactly what
  // simulate() gives for X.col(l), and ok[l] ends as what it returns.
  void simulate_lanes(const Eigen::Ref<const Eigen::MatrixXd>& X, const ModelData& data, LaneMask& ok,
                      const LaneSink& sink) const;
  // Physical values {"gain": .., "hysteresis.A": .., ...} and their units
  // {"gain": "µm/V", ...} given the unit names of u and y.
  nlohmann::json physical_values(const Eigen::Ref<const Eigen::VectorXd>& x,
                                 const SignalScales& scales) const;
  nlohmann::json physical_units(const std::string& u_unit, const std::string& y_unit) const;
  // Inverse of physical_values; every parameter is required. Throws
  // InputError naming the missing or unknown key.
  Eigen::VectorXd from_physical(const nlohmann::json& values, const SignalScales& scales,
                                const std::string& where) const;

 private:
  void build(std::vector<std::string> names, const std::string& where);
  bool simulate_held(const Eigen::Ref<const Eigen::VectorXd>& x, const ModelData& data, Eigen::VectorXd& y,
                     Entry entry, const Eigen::VectorXd* added, ChainSignals* signals) const;

  std::vector<std::string> names_;
  std::vector<ChainEntry> entries_;
  std::vector<EffectParam> params_;  // gain first
  std::vector<std::string> owner_;   // effect of each parameter ("" for the gain)
  int substeps_ = 0;
  InputHold input_hold_ = InputHold::Spline;
};

// Physical scale factor y^y_power · u^u_power of one parameter.
double physical_factor(const EffectParam& p, const SignalScales& scales);

}  // namespace hystbench
