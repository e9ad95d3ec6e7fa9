#include "framework/evolution/current_to_pbest.hpp"

#include "framework/evolution/population.hpp"

namespace hystbench {
namespace {

int draw_pbest(const DePopulationView& pop, int i, bool exclude_target, Rng& rng) {
  int pbest = 0;
  do {
    pbest = pop.order[rng.integer(0, pop.pbest_count - 1)];
  } while (exclude_target && pbest == i);
  return pbest;
}

}  // namespace

Eigen::VectorXd current_to_pbest_mutant(const DePopulationView& pop, const ExternalArchive& archive,
                                        int i, const PbestScales& scales, Rng& rng) {
  const auto& X = pop.X;
  const int np = static_cast<int>(X.cols());
  const int pbest = draw_pbest(pop, i, scales.pbest_excludes_target, rng);
  const int r1 = distinct_indices(rng, np, 1, {i})[0];
  // Indices past the population address the archive.
  const int r2 = distinct_indices(rng, np + archive.size(), 1, {i, r1})[0];
  const Eigen::VectorXd donor = r2 < np ? Eigen::VectorXd(X.col(r2)) : archive.member(r2 - np);
  return X.col(i) + scales.F_pbest * (X.col(pbest) - X.col(i)) + scales.F * (X.col(r1) - donor);
}

}  // namespace hystbench
