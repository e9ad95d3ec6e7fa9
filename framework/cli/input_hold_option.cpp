#include "framework/cli/input_hold_option.hpp"

#include <vector>

namespace hystbench::cli {

void add_input_hold_option(CLI::App* cmd, InputHold& hold, const std::string& causal_use) {
  const std::vector<std::string> names = {to_string(InputHold::Spline), to_string(InputHold::Linear),
                                          to_string(InputHold::Zoh), to_string(InputHold::Bandlimited)};
  // The check runs before the callback, so parse_input_hold never throws here.
  cmd->add_option_function<std::string>(
         "--input-hold",
         [&hold](const std::string& text) { hold = parse_input_hold(text, "--input-hold"); },
         "input between samples for ODE effects: spline (through the record), bandlimited (a "
         "windowed sinc: an input measured behind an anti-alias filter, reaching towards the Nyquist "
         "frequency), or linear or zoh (causal: " + causal_use + ")")
      ->default_str(to_string(InputHold::Spline))
      ->check(CLI::IsMember(names));
}

}  // namespace hystbench::cli
