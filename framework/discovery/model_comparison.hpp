#pragma once
// The comparison of a model's output with the data it was simulated on, in
// physical units: the bridge from ModelData to compare_signals.
#include "framework/discovery/comparison.hpp"
#include "framework/model/model_data.hpp"

namespace hystbench {

// `y_model` in physical units (zeros when the model diverged), over the
// whole record. The warm-up samples (ModelData::warmup) are left out: what
// is compared starts where the scoring does, so no statistic, breakdown or
// figure sees the transient the warm-up absorbs.
ComparisonInput comparison_input(const ModelData& data, Eigen::VectorXd y_model,
                                 const std::string& u_unit, const std::string& y_unit);

// The start-up transient of a model output on its own data, alone: what
// `fit` says without the whole comparison (startup_transient.hpp). `y_model`
// in the units of data.y (normalised), over the whole record.
StartupTransient startup_transient(const ModelData& data, const Eigen::VectorXd& y_model);

}  // namespace hystbench
