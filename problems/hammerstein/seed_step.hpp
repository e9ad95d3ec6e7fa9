#pragma once
// One sample of the 13-parameter seed model (docs/models.md#hammerstein-seed-model):
// the Bouc-Wen loop, the static part, the mass-spring-damper and the ARX
// filter. The scalar model (hammerstein_model.cpp) and the batched fitness
// (batched_sse.cpp) both call it, so a candidate's value is the same bit for
// bit in either.
//
// The recurrences are latency-bound: in each sum the previous sample's state
// is added last, so that only one multiply and one add separate consecutive
// samples.
#include "problems/hammerstein/bouc_wen.hpp"

namespace hystbench {

// The model's memory; every signal is 0 before k = 0.
template <class V>
struct SeedState {
  V h{}, h1_1{}, h1_2{}, r_1{}, r_2{}, r1_1{}, r1_2{};
};

// V: double or LaneVector; Q: RecurrenceCoefficients or a block of them
// (the same fields as V). `drive` is the Bouc-Wen drive (input increment or
// input), `u` the input. Returns the model output at this sample.
template <class V, class Q>
[[gnu::always_inline]] inline V seed_step(SeedState<V>& s, const Q& q, double drive, double abs_drive,
                                          double u) {
  const V h = bouc_wen_step(s.h, drive, abs_drive, q.beta, q.aL, q.gamma);
  const V h1 = q.d1 * u + q.d2 * u * u - h;
  const V r = (q.k_h0 * h1 + q.k_h1 * s.h1_1 + q.k_h2 * s.h1_2 + q.k_r2 * s.r_2) + q.k_r1 * s.r_1;
  const V r1 = (q.a * s.r_1 + q.b * s.r_2 - q.d * s.r1_2) - q.c * s.r1_1;
  s.h = h;
  s.h1_2 = s.h1_1;
  s.h1_1 = h1;
  s.r_2 = s.r_1;
  s.r_1 = r;
  s.r1_2 = s.r1_1;
  s.r1_1 = r1;
  return r1;
}

}  // namespace hystbench
