#pragma once
// The Hammerstein SSE of many candidates at once.
//
// One candidate is a sequential recurrence in time and latency-bound. Across
// candidates it vectorises: candidates are packed structure-of-arrays into
// blocks of the native vector width (8 doubles with AVX-512), a block's
// state stays in registers, and two blocks advance together in time so that
// one block's latency hides behind the other's arithmetic.
//
// Each candidate's value is bit-identical to hammerstein_sse(): the kernel
// performs the scalar recurrence's operations in the same order on every
// lane, contraction into fused multiply-adds is off (CMakeLists.txt), and
// lanes never mix. So the value of a candidate does not depend on its
// neighbours, on the block it landed in, or on the thread count.
#include "framework/core/eigen.hpp"

#include "framework/core/problem.hpp"
#include "problems/hammerstein/hammerstein_model.hpp"

namespace hystbench {

// Doubles per block: the native vector width this library was compiled for.
int batched_sse_lanes();

// f[i] = hammerstein_sse(column i of X, ...) for every column of X
// (13 x n, HammersteinParams::to_vector order); f has size n.
// options.threads OpenMP threads share the blocks (1: the calling thread
// only). With options.abandon_above, a block stops once every lane's partial
// SSE exceeds its limit; such a candidate gets its partial SSE, a value
// above its limit (the SSE only grows), and the others their exact SSE.
// Thread-safe.
void hammerstein_sse_batched(const Eigen::Ref<const Eigen::MatrixXd>& X, const Eigen::VectorXd& u,
                             const Eigen::VectorXd& y, double Ts, BoucWenForm form,
                             Eigen::Ref<Eigen::VectorXd> f, const EvaluationOptions& options = {});

}  // namespace hystbench
