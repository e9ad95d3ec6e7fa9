#pragma once
// The Bouc-Wen loop's update, shared by the seed model (scalar and batched,
// docs/models.md#hammerstein-seed-model) and the hysteresis effect, so that
// the three compute it with the same operations in the same order:
//
//   h ← h + A·d − β·|d|·h − γ·d·|h|
//
// with d the input increment (or, in the paper's form, the input itself).
// Grouped by h so that only one multiply and one add separate consecutive
// samples: the recurrence is latency-bound.
#include "framework/model/effect_lanes.hpp"

namespace hystbench {

// V: double or LaneVector (the loop of one candidate or of a block); D: the
// drive, shared by a block or per lane; C: the coefficients, like V.
template <class V, class D, class C>
[[gnu::always_inline]] inline V bouc_wen_step(V h, D d, D abs_d, C beta, C A, C gamma) {
  return (h * (1.0 - beta * abs_d) + A * d) - gamma * d * lane_abs(h);
}

}  // namespace hystbench
