#include "framework/evolution/real_coded_operators.hpp"

#include <algorithm>
#include <cmath>

#include "framework/core/text.hpp"
#include "framework/evolution/population.hpp"

namespace hystbench {
namespace {

void clip(Eigen::Ref<Eigen::VectorXd> v, const Bounds& bounds) {
  for (Eigen::Index j = 0; j < v.size(); ++j)
    v[j] = std::clamp(v[j], bounds.lower[j], bounds.upper[j]);
}

// Spread factor of one SBX child; beta measures how far the nearer bound is
// (in units of half the parents' distance), so the child never passes it.
double sbx_spread(double beta, double r, double eta) {
  const double alpha = 2.0 - std::pow(beta, -(eta + 1.0));
  const double base = r <= 1.0 / alpha ? r * alpha : 1.0 / (2.0 - r * alpha);
  return std::pow(base, 1.0 / (eta + 1.0));
}

}  // namespace

const std::vector<std::string>& real_crossover_names() {
  static const std::vector<std::string> names{"sbx", "blx-alpha", "arithmetic"};
  return names;
}

RealCrossover real_crossover_from_string(const std::string& name) {
  return static_cast<RealCrossover>(index_of_name(real_crossover_names(), name, "crossover"));
}

const std::vector<std::string>& real_mutation_names() {
  static const std::vector<std::string> names{"polynomial", "polynomial-to-bound", "gaussian"};
  return names;
}

RealMutation real_mutation_from_string(const std::string& name) {
  return static_cast<RealMutation>(index_of_name(real_mutation_names(), name, "mutation"));
}

int tournament(const Eigen::VectorXd& f, int size, Rng& rng) {
  const auto entrants = distinct_indices(rng, static_cast<int>(f.size()), size, {});
  int winner = entrants[0];
  int ties = 1;
  for (std::size_t k = 1; k < entrants.size(); ++k) {
    const int c = entrants[k];
    if (f[c] < f[winner]) {
      winner = c;
      ties = 1;
    } else if (f[c] == f[winner] && rng.integer(1, ++ties) == 1) {
      winner = c;  // reservoir draw: each tied entrant wins with equal chance
    }
  }
  return winner;
}

ChildPair sbx_crossover(const Eigen::VectorXd& y1, const Eigen::VectorXd& y2,
                        const Bounds& bounds, double eta, Rng& rng) {
  ChildPair children{y1, y2};
  for (Eigen::Index j = 0; j < y1.size(); ++j) {
    if (rng.uniform() > 0.5 || std::abs(y1[j] - y2[j]) < 1e-14) continue;
    const double a = std::min(y1[j], y2[j]), b = std::max(y1[j], y2[j]);
    const double lo = bounds.lower[j], hi = bounds.upper[j];
    const double r = rng.uniform();
    const double spread_a = sbx_spread(1.0 + 2.0 * (a - lo) / (b - a), r, eta);
    const double spread_b = sbx_spread(1.0 + 2.0 * (hi - b) / (b - a), r, eta);
    const double near_a = 0.5 * ((a + b) - spread_a * (b - a));
    const double near_b = 0.5 * ((a + b) + spread_b * (b - a));
    const double ca = std::clamp(near_a, lo, hi), cb = std::clamp(near_b, lo, hi);
    const bool keep_order = rng.uniform() < 0.5;
    children.first[j] = keep_order ? ca : cb;
    children.second[j] = keep_order ? cb : ca;
  }
  return children;
}

ChildPair blx_alpha_crossover(const Eigen::VectorXd& y1, const Eigen::VectorXd& y2,
                              const Bounds& bounds, double alpha, Rng& rng) {
  ChildPair children{y1, y2};
  for (Eigen::Index j = 0; j < y1.size(); ++j) {
    const double cmin = std::min(y1[j], y2[j]), cmax = std::max(y1[j], y2[j]);
    const double spread = alpha * (cmax - cmin);
    children.first[j] = rng.uniform(cmin - spread, cmax + spread);
    children.second[j] = rng.uniform(cmin - spread, cmax + spread);
  }
  clip(children.first, bounds);
  clip(children.second, bounds);
  return children;
}

ChildPair arithmetic_crossover(const Eigen::VectorXd& y1, const Eigen::VectorXd& y2,
                               const Bounds& bounds, Rng& rng) {
  const double lambda = rng.uniform();
  ChildPair children{lambda * y1 + (1.0 - lambda) * y2, (1.0 - lambda) * y1 + lambda * y2};
  // Convex combinations stay inside the box up to rounding.
  clip(children.first, bounds);
  clip(children.second, bounds);
  return children;
}

void polynomial_mutation(Eigen::Ref<Eigen::VectorXd> y, const Bounds& bounds, double pm,
                         double eta, Rng& rng) {
  const double m = 1.0 / (eta + 1.0);
  for (Eigen::Index j = 0; j < y.size(); ++j) {
    if (rng.uniform() >= pm) continue;
    const double lo = bounds.lower[j], hi = bounds.upper[j], width = hi - lo;
    if (!(width > 0)) continue;
    const double r = rng.uniform();
    double dq;
    if (r < 0.5) {
      const double d1 = (y[j] - lo) / width;
      dq = std::pow(2.0 * r + (1.0 - 2.0 * r) * std::pow(1.0 - d1, eta + 1.0), m) - 1.0;
    } else {
      const double d2 = (hi - y[j]) / width;
      dq = 1.0 - std::pow(2.0 * (1.0 - r) + 2.0 * (r - 0.5) * std::pow(1.0 - d2, eta + 1.0), m);
    }
    y[j] = std::clamp(y[j] + dq * width, lo, hi);
  }
}

void polynomial_mutation_to_bound(Eigen::Ref<Eigen::VectorXd> y, const Bounds& bounds, double pm,
                                  double eta, Rng& rng) {
  const double m = 1.0 / (eta + 1.0);
  for (Eigen::Index j = 0; j < y.size(); ++j) {
    if (rng.uniform() >= pm) continue;
    const double lo = bounds.lower[j], hi = bounds.upper[j];
    if (!(hi > lo)) continue;
    const double r = rng.uniform();
    if (r <= 0.5)
      y[j] += (std::pow(2.0 * r, m) - 1.0) * (y[j] - lo);  // towards the lower bound
    else
      y[j] += (1.0 - std::pow(2.0 * (1.0 - r), m)) * (hi - y[j]);  // towards the upper one
    y[j] = std::clamp(y[j], lo, hi);
  }
}

void gaussian_mutation(Eigen::Ref<Eigen::VectorXd> y, const Bounds& bounds, double pm,
                       double sigma, Rng& rng) {
  for (Eigen::Index j = 0; j < y.size(); ++j) {
    if (rng.uniform() >= pm) continue;
    y[j] += rng.normal(0.0, sigma * (bounds.upper[j] - bounds.lower[j]));
  }
  clip(y, bounds);
}

}  // namespace hystbench
