#pragma once
// Which samples a fit may not see. Selection (of parameters, of effects) is
// judged on the held-out part too, so it must span the same excitation band
// and the same stretch of time as the part used for fitting.
#include <string>

#include "framework/model/model_data.hpp"

namespace hystbench {

struct HoldoutSpec {
  enum class Mode { Auto, None, Last, Segments, ByFrequency };
  Mode mode = Mode::Auto;
  double fraction = 0.25;             // Last: the final fraction of the record
  std::vector<std::string> segments;  // Segments: the labels held out
  // Leading samples that only initialise the model (ModelData::warmup).
  // Part of the spec so that a fit's record carries it to every later use.
  Eigen::Index warmup = 0;
  // The record starts where a held input leaves the model, not at rest
  // (ModelData::held_start); needs a warm-up.
  bool held_start = false;

  // "auto", "none", "last:0.25", "segments:sine_2Hz,sine_20Hz",
  // "by-frequency", each optionally followed by "+warmup:N" and then
  // "+held". Throws
  // InputError naming `where` and the accepted forms.
  static HoldoutSpec parse(const std::string& text, const std::string& where = "--holdout");
  std::string text() const;

 private:
  static HoldoutSpec parse_part(const std::string& text, const std::string& where);
  std::string part_text() const;  // text() without the warm-up
};

// Marks the held-out samples in data.estimation (0 = held out), then the
// warm-up (0 as well, and data.warmup set).
//
// Auto holds out the last quarter of every segment run (of each of eight
// equal blocks when the data have no segment column). Model selection is
// judged on the held-out part, so it must hold every excitation frequency
// and amplitude that the fit sees: a hold-out of whole segments keeps a band
// (say the one at a resonance) out of every fit and rewards effects that
// happen to extrapolate into it.
//
// ByFrequency (the former default) ranks whole segments by their dominant
// input frequency and holds out a quarter of them at evenly spaced inner
// ranks: a test of extrapolation to unseen frequencies, not a selection
// hold-out. With fewer than four segments it falls back to Auto.
//
// Throws InputError when a named segment does not exist, the warm-up is not
// shorter than the record, a held start has no warm-up, or nothing would be
// left to fit.
void apply_holdout(ModelData& data, const HoldoutSpec& spec);

// One sentence for reports: what `spec` held out of `data` and why.
std::string describe_holdout(const ModelData& data, const HoldoutSpec& spec);

}  // namespace hystbench
