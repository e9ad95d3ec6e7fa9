#pragma once
// JADE/SHADE external archive: parents beaten by their trials, kept as extra
// donors for the second difference vector (docs/algorithms.md#external-archive).
#include "framework/core/eigen.hpp"
#include <vector>

#include "framework/core/rng.hpp"

namespace hystbench {

class ExternalArchive {
 public:
  int size() const { return static_cast<int>(members_.size()); }
  const Eigen::VectorXd& member(int k) const { return members_[k]; }

  void add(const Eigen::Ref<const Eigen::VectorXd>& x) { members_.emplace_back(x); }
  // Deletes uniformly random members until at most `capacity` remain.
  void shrink_to(int capacity, Rng& rng);

 private:
  std::vector<Eigen::VectorXd> members_;
};

// Archive capacity round(rate * NP).
int archive_capacity(double rate, int np);

}  // namespace hystbench
