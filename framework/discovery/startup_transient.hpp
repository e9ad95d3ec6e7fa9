#pragma once
// Does a start-up transient dominate the error? A model started at rest
// follows a measured record only after its states (the hysteresis
// variable, a resonance, creep) have caught up with the actuator's, so the
// first period of every excited part (excitation_content.hpp) can hold an
// error the rest of the record does not have: a Bouc-Wen loop started at
// z = 0 draws a virgin curve where the actuator, already cycled, draws its
// loop. When those first periods hold far more than their share of the
// squared error, the fit is decided by the transient, not by the physics
// of the rest; the cure is a warm-up (--warmup), not another effect, and
// discovery prunes none of the start model's effects on that evidence.
#include "framework/core/eigen.hpp"
#include <nlohmann/json.hpp>
#include <string>

#include "framework/discovery/excitation_content.hpp"

namespace hystbench {

// The first periods dominate when they hold at least this share of the
// squared error and this many times their share of the samples.
inline constexpr double kTransientErrorShare = 0.2;
inline constexpr double kTransientConcentration = 4.0;

// A record that starts away from where the model starts (a tank half full,
// an actuator held at a voltage, against a model at rest): the first
// samples' error is a level at least this many times the RMSE.
inline constexpr double kStartLevelRatio = 3.0;

// The transient has settled where a block's RMS error is at most this many
// times the record's median block RMS, for this many blocks in a row.
inline constexpr double kSettledRatio = 2.0;
inline constexpr Eigen::Index kSettledBlocks = 8;

struct StartupTransient {
  bool dominates = false;
  double error_share = 0;   // of the squared error, in the first periods
  double sample_share = 0;  // of the samples
  // The advised warm-up: samples up to where the first excited part's error
  // has settled (kSettledRatio) within the part's first half; otherwise, and
  // never earlier than, the end of its first period.
  Eigen::Index warmup = 0;
  Eigen::Index first_period_end = 0;
  // The first samples' error is a level kStartLevelRatio times the RMSE or
  // more. Advice only: unlike `dominates` it changes no decision.
  bool starts_away = false;
  double start_ratio = 0;  // RMS error of the first samples / RMSE
  // Whether there is anything to tell the user (sentence() is not empty).
  bool worth_saying() const { return dominates || starts_away; }
  // Says where it sits and what to do; empty when neither holds.
  std::string sentence() const;
  nlohmann::json to_json() const;
};

// `e`: the residual of the compared samples; `excitation` of the same
// samples; `first_sample`: where in the record they start (the warm-up's
// length), so that the advice counts from the record's start.
StartupTransient find_startup_transient(const Eigen::VectorXd& e, const ExcitationContent& excitation,
                                        Eigen::Index first_sample = 0);

}  // namespace hystbench
