#pragma once
// --input-hold for the commands that simulate a model: how ODE effects
// reconstruct the input between samples (framework/model/input_hold.hpp).
// The offline default is the spline; `causal_use` says what a causal hold
// is for on that command.
#include <CLI/CLI.hpp>
#include <string>

#include "framework/model/input_hold.hpp"

namespace hystbench::cli {

void add_input_hold_option(CLI::App* cmd, InputHold& hold, const std::string& causal_use);

}  // namespace hystbench::cli
