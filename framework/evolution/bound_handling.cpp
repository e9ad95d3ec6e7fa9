#include "framework/evolution/bound_handling.hpp"

#include "framework/core/text.hpp"

#include <algorithm>
#include <stdexcept>

namespace hystbench {
namespace {

double repair_component(double v, double parent, double lo, double hi, BoundHandling rule,
                        Rng& rng) {
  switch (rule) {
    case BoundHandling::Midpoint:
      return v < lo ? (lo + parent) / 2 : (hi + parent) / 2;
    case BoundHandling::Clip:
      return std::clamp(v, lo, hi);
    case BoundHandling::Reinit:
      return rng.uniform(lo, hi);
    case BoundHandling::Reflect: {
      const double r = v < lo ? 2 * lo - v : 2 * hi - v;
      return (r >= lo && r <= hi) ? r : rng.uniform(lo, hi);
    }
  }
  return std::clamp(v, lo, hi);
}

}  // namespace

const std::vector<std::string>& bound_handling_names() {
  static const std::vector<std::string> names{"midpoint", "clip", "reinit", "reflect"};
  return names;
}

BoundHandling bound_handling_from_string(const std::string& name) {
  return static_cast<BoundHandling>(index_of_name(bound_handling_names(), name, "bound handling"));
}

ParamSpec bound_handling_param() {
  return ParamSpec::choice("bounds", "midpoint", bound_handling_names(),
                           "repair of trial components outside the box");
}

void repair(Eigen::Ref<Eigen::VectorXd> v, const Eigen::Ref<const Eigen::VectorXd>& parent,
            const Bounds& bounds, BoundHandling rule, Rng& rng) {
  for (Eigen::Index j = 0; j < v.size(); ++j) {
    const double lo = bounds.lower[j], hi = bounds.upper[j];
    if (v[j] < lo || v[j] > hi) {
      // Midpoint of a parent on the bound can round past it; clamp keeps
      // the promise that repaired points are inside.
      v[j] = std::clamp(repair_component(v[j], parent[j], lo, hi, rule, rng), lo, hi);
    }
  }
}

}  // namespace hystbench
