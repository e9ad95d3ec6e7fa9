#include "framework/model/input_hold.hpp"

#include "framework/core/error.hpp"

namespace hystbench {

std::string to_string(InputHold hold) {
  switch (hold) {
    case InputHold::Spline: return "spline";
    case InputHold::Linear: return "linear";
    case InputHold::Zoh: return "zoh";
    case InputHold::Bandlimited: return "bandlimited";
  }
  return "?";
}

InputHold parse_input_hold(const std::string& text, const std::string& where) {
  for (InputHold hold : {InputHold::Spline, InputHold::Linear, InputHold::Zoh, InputHold::Bandlimited})
    if (text == to_string(hold)) return hold;
  throw InputError(where + ": unknown input hold '" + text + "'; valid: spline, linear, zoh, bandlimited");
}

bool is_causal(InputHold hold) { return hold == InputHold::Linear || hold == InputHold::Zoh; }

}  // namespace hystbench
