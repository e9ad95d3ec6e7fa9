#pragma once
// Which samples a fit may not see. Selection (of parameters, of effects) is
// judged on the held-out part too, so it must span the same excitation band
// and the same stretch of time as the part used for fitting.
#include <string>

#include "framework/model/model_data.hpp"

namespace hystbench {

struct HoldoutSpec {
  enum class Mode { Auto, None, Last, Segments };
  Mode mode = Mode::Auto;
  double fraction = 0.25;             // Last: the final fraction of the record
  std::vector<std::string> segments;  // Segments: the labels held out

  // "auto", "none", "last:0.25", "segments:sine_2Hz,sine_20Hz". Throws
  // InputError naming `where` and the accepted forms.
  static HoldoutSpec parse(const std::string& text, const std::string& where = "--holdout");
  std::string text() const;
};

// Marks the held-out samples in data.estimation (0 = held out).
//
// Auto with four or more segments: the segments are ranked by their dominant
// input frequency (zero crossings), and a quarter of them (at least one) is
// held out at evenly spaced inner ranks, so that neither part keeps only the
// low or only the high frequencies; with one to three segments the last
// quarter of every segment; without segments the last quarter of the record.
// Throws InputError when a named segment does not exist or nothing would be
// left to fit.
void apply_holdout(ModelData& data, const HoldoutSpec& spec);

}  // namespace hystbench
