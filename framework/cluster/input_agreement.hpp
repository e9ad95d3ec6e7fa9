#pragma once
// Before the first trial message, every rank says whether it could read its
// inputs and what it read (MPI build). All ranks reach the same verdict from
// the same exchanged facts, so they stop together with one message and the
// same exit code, or start together.
#include "framework/core/problem.hpp"
#include "framework/harness/experiment.hpp"

namespace hystbench::cluster {

// Collective, on a rank that read its inputs. Returns when every rank did and
// read the same; otherwise rank 0 throws InputError naming the rank that read
// something else, and a rank with nothing to report throws RankStopped.
void agree_inputs_read(const Experiment& experiment, const Problem& problem);

// Collective, on a rank that could not read its inputs (exit_code 1 or 2).
// Returns when this rank reports its own error (rank 0, or any rank when rank
// 0 was fine); throws RankStopped when rank 0 reports one.
void agree_inputs_failed(int exit_code);

// Whether this rank took part in the agreement already.
bool inputs_agreed();

}  // namespace hystbench::cluster
