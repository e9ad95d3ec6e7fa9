#pragma once
// Physical effects: the building blocks of discovery models (docs/architecture.md#effect-plugins).
//
// A model is an ordered list of effects in a fixed signal chain
//
//   u -> [input] -> gain·v + [nonlinearity] -> [dynamics] -> [output] -> y
//
// Each effect is a plugin registered with one macro:
//
//   class MyEffect : public hystbench::Effect {
//    public:
//     static hystbench::EffectInfo info();   // name, stage, parameters, signature statistic
//     bool apply(std::span<const double> p, const hystbench::SignalContext& ctx,
//                Eigen::Ref<Eigen::VectorXd> signal) const override;
//     // Optional: stepper() (streaming) and lane_run() (batched); an effect
//     // deriving from KernelEffect (kernel_effect.hpp) gets all three from
//     // one per-sample kernel.
//   };
//   HYSTBENCH_EFFECT(MyEffect)
//
// Effects work in normalised units: the framework divides u and y by their
// RMS before fitting, so bounds are O(1) whatever the physical units, and
// converts parameters back for reports (EffectParam::y_power / u_power).
#include "framework/core/eigen.hpp"
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "framework/core/registry.hpp"
#include "framework/model/effect_lanes.hpp"
#include "framework/model/effect_stepper.hpp"
#include "framework/model/input_hold.hpp"
#include "framework/model/residual_signature.hpp"

namespace hystbench {

enum class EffectStage { Input, Nonlinearity, Dynamics, Output };

// "input", "nonlinearity", "dynamics", "output".
std::string stage_name(EffectStage stage);

struct EffectParam {
  std::string name;
  // Bounds and neutral value in normalised units. At the neutral value of
  // all its parameters the effect leaves the signal exactly unchanged.
  double lower = 0.0;
  double upper = 0.0;
  double neutral = 0.0;
  // Physical value = normalised value · y_rms^y_power · u_rms^u_power, in
  // the unit `unit` · y^y_power · u^u_power (e.g. y_power 1, u_power -1:
  // µm/V). Parameters in s, Hz or plain numbers keep both powers at 0.
  int y_power = 0;
  int u_power = 0;
  std::string unit;
  std::string doc;
  // A shape parameter (saturation's softness): it matters only while the
  // effect's other parameters are away from neutral, so it is left out of
  // the "does nothing within noise" test, where it is undetermined; and its
  // bounds are shapes of their own (softness 0 is a hard clip), so sitting
  // on one is no sign of a search range too narrow.
  bool shape = false;
};

// What an effect sees besides its own parameters and signal.
struct SignalContext {
  double sample_time = 0.0;                     // s
  const Eigen::VectorXd* time = nullptr;        // s, starting at 0
  // The signal as it entered this effect's stage: u for input effects, v
  // (normalised input after the input stage, before the gain) for
  // nonlinearity effects, w (the nonlinearity's output) for dynamics
  // effects, and the dynamics' output for output effects. Lets parallel
  // branches (a second vibration mode, a hysteresis term) see the stage input.
  const Eigen::VectorXd* stage_input = nullptr;
  // Internal integration sub-steps per sample for effects that integrate an
  // ODE (a model option; 0 = the effect's own default).
  int substeps = 0;
  // How such effects reconstruct their input between samples (a model
  // option, input_hold.hpp). Last, so that aggregate initialisations
  // written before it existed keep the offline default.
  InputHold hold = InputHold::Spline;
};

// What a block of candidates is run with (Model::simulate_lanes): the
// SignalContext fields that are the same for every chunk.
struct LaneContext {
  double sample_time = 0.0;  // s
  int substeps = 0;
  InputHold hold = InputHold::Spline;
};

class Effect {
 public:
  virtual ~Effect() = default;
  // Transforms `signal` in place; `p` holds the parameters in declared order
  // (normalised units). Returns false when `p` makes the effect unstable or
  // meaningless: the model's output is then +inf, never NaN.
  virtual bool apply(std::span<const double> p, const SignalContext& ctx,
                     Eigen::Ref<Eigen::VectorXd> signal) const = 0;

  // Optional batched form (effect_lanes.hpp): kEffectLanes candidates at
  // once, run a chunk of samples at a time (the whole record in one chunk
  // when its LaneRun asks for it). Over all chunks it must leave
  // every lane exactly as apply() leaves it and clear ok[l] (here or in
  // finish()) where apply() would return false. A model all of whose
  // effects have it evaluates candidates in blocks; otherwise one at a time.
  // kernel_effect.hpp writes it from the effect's per-sample kernel.
  virtual bool has_lanes() const { return false; }
  virtual std::unique_ptr<LaneRun> lane_run(const LaneParams& /*p*/, const LaneContext& /*ctx*/,
                                            LaneMask& /*ok*/) const {
    return nullptr;
  }

  // Streaming form (effect_stepper.hpp): the effect one sample at a time,
  // for StreamingModel. Null when `p` is invalid. The default replays
  // apply() on the whole history at every sample (replay_stepper.hpp):
  // exact for any causal effect but O(k) per sample, so effects that may
  // run in long streams override it. The stepper may refer to this effect.
  virtual std::unique_ptr<EffectStepper> stepper(std::span<const double> p,
                                                 const StepContext& ctx) const;
};

// What a record must excite to tell two effects apart that can take over
// each other's role (docs/discovery.md, "What the record can tell apart").
enum class ExcitationNeed {
  SeveralFrequencies,  // a rate-dependent rival draws the same loop at one frequency
  SeveralAmplitudes,   // an amplitude-dependent rival matches at one amplitude
  HeldLevel,           // slow effects differ only after the input holds a new level
};

// An effect that can carry this one's role on a record that does not
// excite `need`.
struct EffectRival {
  std::string effect;
  ExcitationNeed need;
};

struct EffectInfo {
  std::string name;     // catalog name, as written in --model lists
  std::string summary;  // one line: the physical effect
  std::string citation;
  EffectStage stage = EffectStage::Output;
  std::vector<EffectParam> params;
  // Residual signature that points at this effect (docs/discovery.md), as one
  // plain sentence completing "adding <name> helps because ...".
  std::string signature;
  // The statistic of the current residual that measures that signature, and
  // the sentence that cites it (residual_signature.hpp): the evidence for
  // this effect. Statistics and their helpers: framework/model/regressors.hpp.
  ResidualSignature statistic = {};
  // Name of an effect this one generalises (e.g. a Bouc-Wen oscillator
  // generalises msd): adding it replaces that effect, carrying over the
  // parameters of the same name. Empty for most effects.
  std::string extends;
  // Effects that take over this one's role where the record does not excite
  // what tells them apart (hysteresis and a linear lag at one frequency).
  // Either side may declare the pair.
  std::vector<EffectRival> rivals;
  // What the fitted parameters (normalised units, declared order) make of
  // the effect where its name would mislead: a Bouc-Wen force with no loop
  // is a spring, not hysteresis. Returns a sentence, or "" when the name
  // says it. Optional.
  std::function<std::string(std::span<const double>)> reading = nullptr;
  // Filled in by HYSTBENCH_EFFECT.
  std::function<std::unique_ptr<Effect>()> create = nullptr;
};

using EffectRegistry = Registry<EffectInfo>;

}  // namespace hystbench

#define HYSTBENCH_EFFECT(Class) HYSTBENCH_REGISTER_PLUGIN(::hystbench::EffectInfo, Class)
