#pragma once
// The figures of a control experiment (docs/control.md#outputs), from the
// first noise seed of every compared controller, as gnuplot scripts like
// every other hystbench figure:
//
//   residual_error  1 s moving RMS of the true error, dB re the uncontrolled level
//   step_size       the step size mu(n)
//   weight_norm     |w(n)|
//   spectrum        Welch spectrum of the true (noise-free) error over the
//                   steady window, uncontrolled and controlled: what the
//                   controller left beneath the sensor noise
//
// The data go to traces.csv (every `decimate`-th sample) and spectrum.csv.
#include <filesystem>
#include <vector>

#include "framework/control/control_run.hpp"

namespace hystbench {

// Returns the scripts written (render them with render_figures).
std::vector<std::filesystem::path> write_control_figures(const std::filesystem::path& dir,
                                                         const ControlExperiment& x,
                                                         const ControlResults& results);

}  // namespace hystbench
