#pragma once
// The noise floor σ of a measured output: the RMSE a perfect model would
// reach. A fit whose RMSE is close to σ has nothing left to find.
//
// Methods, tried in this order:
//  "periodic"        u repeats exactly (to 1e-6 of its range) with a period of
//                    P ≥ 4 samples, at least twice, inside a segment run or over
//                    the whole record; or a segment label comes back (three or
//                    more runs) with the same length and the same input (RMS
//                    difference ≤ 5 % of its spread), each run being one period.
//                    Then y_p − y_{p+1} holds only noise:
//                    σ = RMS(y_k − y_{k+P}) / √2 over the second half of the
//                    periods of each stretch (pairs p, p+1 with p ≥ ⌊m/2⌋ of m
//                    periods): the first periods carry the start-up transient,
//                    so a stretch needs three or more periods.
//  "spectral"        otherwise, when the input has power above fs/6 (at
//                    least 1e-3 of its Welch peak), where no difference of y
//                    removes the signal (|2 sin(πf/fs)| ≥ 1): σ from the
//                    output's power in the bins where the input has none
//                    (below 1e-4 of its peak; at least 16 bins and an eighth
//                    of them), median power / Σw² of the Hann window, as white
//                    noise would give. A sensor's anti-alias filter lowers the
//                    noise there, so this errs low, while differences would
//                    count the signal as noise.
//  "difference_mad"  otherwise: m-th differences d_k = Σ_j (−1)^j C(m,j) y_{k+j}
//                    remove a smooth signal while white noise keeps variance
//                    C(2m,m)σ²; σ_m = 1.4826·median|d| / √C(2m,m) (robust to the
//                    bursts at steps), and σ = min over m = 2..6.
//  "none"            fewer than 8 samples: σ is NaN.
#include "framework/core/eigen.hpp"
#include <string>
#include <vector>

namespace hystbench {

// Fewest samples of an estimate (differences up to order 6 need 8); with
// fewer the method is "none".
constexpr Eigen::Index kNoiseFloorFewestSamples = 8;

struct NoiseFloor {
  double sigma = 0;
  std::string method;       // "periodic", "spectral", "difference_mad" or "none"
  long pairs = 0;           // periodic: sample pairs compared; spectral: quiet bins
  Eigen::Index period = 0;  // periodic from u: period in samples of the first stretch used
                            // (0 for repeated labels)
  int order = 0;            // difference_mad: order m that gave the minimum
  double quiet_from = 0;    // spectral: lowest quiet frequency, as a fraction of fs
};

NoiseFloor estimate_noise_floor(const Eigen::VectorXd& u, const Eigen::VectorXd& y,
                                const std::vector<std::string>& segment);

// The difference-based estimate alone (method "difference_mad").
NoiseFloor difference_noise_floor(const Eigen::VectorXd& y);

}  // namespace hystbench
