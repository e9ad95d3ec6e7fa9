#pragma once
// Velocity coefficients of particle swarm optimisation (docs/algorithms.md#pso).
namespace hystbench {

// Linearly decreasing inertia weight w = w_max - (w_max - w_min) tau, tau =
// fraction of the budget used (Shi & Eberhart).
double inertia_weight(double w_max, double w_min, double tau);

// Clerc-Kennedy constriction chi = 2 kappa / |2 - phi - sqrt(phi^2 - 4 phi)|
// for phi = c1 + c2. Throws std::invalid_argument unless phi > 4.
double constriction_factor(double phi, double kappa = 1.0);

}  // namespace hystbench
