#pragma once
// How a sampled input is reconstructed between its samples, for effects that
// integrate an ODE with several internal steps per sample
// (docs/models.md#streaming-models). One choice, used by the batch
// simulation (Model::simulate) and by the sample-by-sample stream
// (StreamingModel) alike:
//
//   spline  a not-a-knot cubic spline through the whole record: exact for
//           cubics, the default for offline fits; but not causal: the value
//           between samples k and k+1 depends on every sample of the record,
//           later ones included.
//   bandlimited
//           a windowed sinc over 24 neighbouring samples
//           (band_limited_interpolation.hpp): what a band-limited input is
//           between its samples, closer than the spline where the input
//           reaches towards the Nyquist frequency. Not causal either.
//   linear  straight lines between samples: the value on [k, k+1] depends on
//           samples k and k+1 only. Causal; the stream's default.
//   zoh     the input held at sample k until sample k+1 (zero-order hold, as
//           a DAC does): strictly causal, the least accurate.
//
// Effects without an ODE ignore the choice.
#include <string>

namespace hystbench {

enum class InputHold { Spline, Linear, Zoh, Bandlimited };

// "spline", "linear", "zoh", "bandlimited".
std::string to_string(InputHold hold);
// The inverse; throws InputError naming `where` and the valid names.
InputHold parse_input_hold(const std::string& text, const std::string& where);
// True when the reconstruction on [k, k+1] uses no sample after k+1, so a
// stream can compute it as the samples arrive.
bool is_causal(InputHold hold);

// Input at fraction s in [0, 1] of the interval from sample value w0 to w1
// under a causal hold (linear or zoh; the spline and the band-limited hold
// need the whole record).
inline double held_value(InputHold hold, double w0, double w1, double s) {
  return hold == InputHold::Zoh ? w0 : w0 + s * (w1 - w0);
}

}  // namespace hystbench
