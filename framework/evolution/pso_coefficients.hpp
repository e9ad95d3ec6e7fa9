#pragma once
// Velocity coefficients of particle swarm optimisation (algorithms.md §6).
namespace hystbench {

// Linearly decreasing inertia weight w = w_max - (w_max - w_min) tau (§6.1),
// tau = fraction of the budget used.
double inertia_weight(double w_max, double w_min, double tau);

// Clerc-Kennedy constriction chi = 2 kappa / |2 - phi - sqrt(phi^2 - 4 phi)|
// for phi = c1 + c2 (§6.2). Throws std::invalid_argument unless phi > 4.
double constriction_factor(double phi, double kappa = 1.0);

}  // namespace hystbench
