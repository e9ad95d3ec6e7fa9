#pragma once
// A record that does not start at rest (docs/discovery.md, "Measured records
// as they come"): a tank half full, an actuator held at a voltage. Its
// initial state is estimated as the state the model reaches when the input
// has been held at one level for a long time, the level chosen so that the
// model matches the measured warm-up samples (ModelData::warmup). One
// number per record, found anew for every parameter vector, so a fit and
// every later record are scored the same way, and the effects need no
// state-setting code of their own. A term added to the chain by
// simulate_probed (propose's regressors) is zero before the record and
// leaves the level where the model without it put it.
#include "framework/core/eigen.hpp"

#include "framework/model/model_data.hpp"

namespace hystbench {

class Model;

// Samples of held input run before the record: long enough for the slow
// dynamics the catalog can fit (periods up to a few hundred samples) to settle.
inline constexpr Eigen::Index kHeldStartSamples = 1000;

// `data` with `samples` samples of input `level` before it, at negative
// times; they count as warm-up, and the copy starts at rest.
ModelData with_held_input(const ModelData& data, double level, Eigen::Index samples);

// The held input level (normalised units) at which `model` with parameters
// `x` matches the mean of the measured warm-up output of `data`, searched
// over the record's input range widened by half its span (an end where the
// model diverges moves in to the record's range, then to its middle); the
// end nearer to a match when none inside matches. False when the model
// diverges there too.
bool held_level(const Model& model, const Eigen::Ref<const Eigen::VectorXd>& x, const ModelData& data,
                double& level);

}  // namespace hystbench
