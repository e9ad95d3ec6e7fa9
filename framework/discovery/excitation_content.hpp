#pragma once
// What a record excites: which frequencies and amplitudes, where the input
// rests and for how long, and how many periods each part holds. Two effects
// that can take over each other's role are told apart only by an
// excitation that makes them differ (a rate-independent loop and a linear
// lag draw the same ellipse at one frequency), so discovery asks this
// before it adds or prunes an effect (separability.hpp).
#include "framework/core/eigen.hpp"
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/model/effect.hpp"

namespace hystbench {

// One stretch of a segment run in which the input moves (between rests).
struct ExcitedPart {
  std::string label;                // the segment's, or empty
  Eigen::Index begin = 0, end = 0;  // samples [begin, end)
  bool tone = false;                // one frequency holds most of the power
  double frequency_hz = 0;          // tone: its frequency; otherwise the band's centre
  double low_hz = 0, high_hz = 0;   // the band holding 90 % of the power
  double amplitude_low = 0, amplitude_high = 0;  // half peak-to-peak over periods (units of u)
  double periods = 0;               // length in periods of frequency_hz
};

// A stretch in which the input holds a level.
struct RestPart {
  Eigen::Index begin = 0, end = 0;
  double level = 0;
  bool after_change = false;  // the input held another level or moved before it
};

struct ExcitationContent {
  double sample_time = 0;
  std::vector<ExcitedPart> parts;
  std::vector<RestPart> rests;
  std::vector<double> tones_hz;  // distinct tone frequencies, ascending (10 % apart)
  double low_hz = 0, high_hz = 0;             // over every part
  double amplitude_low = 0, amplitude_high = 0;  // over every part
  std::string u_unit;

  // Whether the record holds what `need` asks (docs/discovery.md, "What the
  // record can tell apart").
  bool meets(ExcitationNeed need) const;
  double rest_seconds() const;
  // What the record holds of what `need` asks: "one frequency (1 Hz)".
  std::string holds(ExcitationNeed need) const;
  // "The record excites one frequency (1 Hz) at one amplitude (75 V): 1
  // excited part holding 10 periods in all, 3 s at rest in 1 stretch."
  std::string summary() const;
  nlohmann::json to_json() const;
};

// Frequencies closer than this ratio count as one; amplitudes likewise.
inline constexpr double kDistinctRatio = 1.1;
// Several frequencies: the band spans at least this ratio.
inline constexpr double kFrequencySpan = 2.0;
// Several amplitudes: the largest at least this times the smallest.
inline constexpr double kAmplitudeSpan = 1.5;
// A rest: the input within 2 % of its range for at least 0.1 s (and 20 samples).
inline constexpr double kRestTolerance = 0.02;
inline constexpr double kShortestRestSeconds = 0.1;
// A held level that separates creep from drift and offset: 0.5 s after a change.
inline constexpr double kHeldLevelSeconds = 0.5;

// `u` in physical units; `segment` one label per sample or empty.
ExcitationContent describe_excitation(const Eigen::VectorXd& u, const std::vector<std::string>& segment,
                               double sample_time, const std::string& u_unit = "");

// What to record so that `need` is met, as advice to the user.
std::string excitation_advice(ExcitationNeed need);
// What `need` asks, in a few words ("several frequencies").
std::string need_text(ExcitationNeed need);

}  // namespace hystbench
