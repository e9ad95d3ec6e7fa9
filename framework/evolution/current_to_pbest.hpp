#pragma once
// DE/current-to-pBest-w/1 with an external archive, the SHADE family's
// mutation (docs/algorithms.md#shade-family):
//   v = x_i + F_pbest (x_pbest - x_i) + F (x_r1 - x~_r2)
// L-SHADE uses F_pbest = F; jSO weights F_pbest by stage.
#include "framework/core/eigen.hpp"

#include "framework/core/rng.hpp"
#include "framework/evolution/de_operators.hpp"
#include "framework/evolution/external_archive.hpp"

namespace hystbench {

struct PbestScales {
  double F_pbest;  // scale of x_pbest - x_i
  double F;        // scale of x_r1 - x~_r2
  bool pbest_excludes_target = false;  // iL-SHADE/jSO early-phase rule
};

// x_pbest uniform among the pop.pbest_count best; r1 in P \ {i};
// x~_r2 in (P u A) \ {i, r1}. Requires P to have at least 3 members
// or an archive making up the difference.
Eigen::VectorXd current_to_pbest_mutant(const DePopulationView& pop, const ExternalArchive& archive,
                                        int i, const PbestScales& scales, Rng& rng);

}  // namespace hystbench
