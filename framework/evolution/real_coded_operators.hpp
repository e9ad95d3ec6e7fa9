#pragma once
// Variation and selection operators of the real-coded GA (docs/algorithms.md#ga):
// binary (k-ary) tournament, bounded SBX and bounded polynomial mutation in
// the NSGA-II formulation, and the switchable alternatives
// (docs/algorithms.md#alternative-operators). Every
// child they return lies inside the box.
#include "framework/core/eigen.hpp"
#include <string>
#include <utility>
#include <vector>

#include "framework/core/problem.hpp"
#include "framework/core/rng.hpp"

namespace hystbench {

using ChildPair = std::pair<Eigen::VectorXd, Eigen::VectorXd>;

enum class RealCrossover { Sbx, BlxAlpha, Arithmetic };
enum class RealMutation { Polynomial, PolynomialToBound, Gaussian };

const std::vector<std::string>& real_crossover_names();  // "sbx", "blx-alpha", "arithmetic"
RealCrossover real_crossover_from_string(const std::string& name);
const std::vector<std::string>& real_mutation_names();  // "polynomial", "polynomial-to-bound", "gaussian"
RealMutation real_mutation_from_string(const std::string& name);

// Index of the winner of a tournament among `size` distinct members drawn
// uniformly: lowest f wins, ties are broken uniformly at random.
int tournament(const Eigen::VectorXd& f, int size, Rng& rng);

// Bounded simulated binary crossover with distribution index eta
// (docs/algorithms.md#bounded-sbx).
ChildPair sbx_crossover(const Eigen::VectorXd& y1, const Eigen::VectorXd& y2,
                        const Bounds& bounds, double eta, Rng& rng);
// BLX-alpha: each component uniform in the parents' interval widened by
// alpha times its length on both sides, then clipped
// (docs/algorithms.md#alternative-operators).
ChildPair blx_alpha_crossover(const Eigen::VectorXd& y1, const Eigen::VectorXd& y2,
                              const Bounds& bounds, double alpha, Rng& rng);
// Whole-vector arithmetic crossover with one lambda = U(0,1) per pair
// (docs/algorithms.md#alternative-operators).
ChildPair arithmetic_crossover(const Eigen::VectorXd& y1, const Eigen::VectorXd& y2,
                               const Bounds& bounds, Rng& rng);

// Bounded polynomial mutation with index eta, each component with
// probability pm (docs/algorithms.md#polynomial-mutation).
void polynomial_mutation(Eigen::Ref<Eigen::VectorXd> y, const Bounds& bounds, double pm,
                         double eta, Rng& rng);
// Polynomial mutation as pagmo2's sga applies it: the same distribution of
// delta with index eta, but scaled by the distance from y_j to the bound it
// moves towards instead of the box width (docs/algorithms.md#polynomial-mutation).
// Near the middle of the box its steps are half as long.
void polynomial_mutation_to_bound(Eigen::Ref<Eigen::VectorXd> y, const Bounds& bounds, double pm,
                                  double eta, Rng& rng);
// y_j += N(0, sigma (u_j - l_j)) with probability pm per component, then
// clipped (docs/algorithms.md#alternative-operators).
void gaussian_mutation(Eigen::Ref<Eigen::VectorXd> y, const Bounds& bounds, double pm,
                       double sigma, Rng& rng);

}  // namespace hystbench
