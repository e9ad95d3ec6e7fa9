#pragma once
// The problem as both frameworks see it: a box and a fitness. Plain standard
// types only, because the pagmo side is compiled with Eigen settings that
// match the Debian pagmo library, not ours, and no Eigen object may cross.
#include <cstddef>
#include <functional>
#include <vector>

namespace hystbench::peer {

struct BoxFitness {
  std::vector<double> lower;
  std::vector<double> upper;
  // f[i] = fitness of candidate i, whose dimension() components start at
  // x + i * dimension() (candidates one after another, as pagmo lays them out).
  std::function<void(const double* x, std::size_t n, double* f)> evaluate;

  std::size_t dimension() const { return lower.size(); }
};

}  // namespace hystbench::peer
