#pragma once
// Repair of components that left the box (docs/algorithms.md#bound-handling). Shared by
// every population method so that "midpoint" means the same everywhere.
#include "framework/core/eigen.hpp"
#include <string>
#include <vector>

#include "framework/core/parameters.hpp"
#include "framework/core/problem.hpp"
#include "framework/core/rng.hpp"

namespace hystbench {

enum class BoundHandling {
  Midpoint,  // halfway between the parent and the violated bound (SHADE family)
  Clip,      // projection onto the box
  Reinit,    // uniform redraw inside the bounds
  Reflect,   // mirror at the bound; redraw if still outside
};

const std::vector<std::string>& bound_handling_names();
BoundHandling bound_handling_from_string(const std::string& name);

// The "bounds" parameter every DE-family plugin declares (default midpoint).
ParamSpec bound_handling_param();

// Repairs every violating component of `v` in place; `parent` is the target
// vector (DE) or current position (PSO, Jaya).
void repair(Eigen::Ref<Eigen::VectorXd> v, const Eigen::Ref<const Eigen::VectorXd>& parent,
            const Bounds& bounds, BoundHandling rule, Rng& rng);

}  // namespace hystbench
