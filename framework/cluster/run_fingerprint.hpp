#pragma once
// What a rank read, in one number: ranks with the same fingerprint run the
// same trials to the same results. It covers the experiment as run (command
// line overrides included), the search box, and the fitness at the centre of
// the box, so that two machines holding different copies of a data file
// disagree before any trial runs rather than mix their results.
#include <cstdint>

#include "framework/core/problem.hpp"
#include "framework/harness/experiment.hpp"

namespace hystbench::cluster {

std::uint64_t run_fingerprint(const Experiment& experiment, const Problem& problem);

}  // namespace hystbench::cluster
