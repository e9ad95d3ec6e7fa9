#pragma once
// Levenberg-Marquardt local search on a least-squares problem, through the
// evaluation context (MINPACK's lmder as ported in Eigen's unsupported
// NonLinearOptimization module).
//
// Why it exists beside the NLopt methods: the Hammerstein fitness is a sum
// of squares, and a method that sees the residual vector converges in a few
// hundred evaluations where BOBYQA, which sees only the sum, needs
// thousands (results/performance/README.md, "Time to quality").
//
// Every residual vector the method asks for is one counted evaluation: the
// context evaluates the candidate (so budget, best point and trace are the
// context's as for every optimizer), and the residuals of a finite
// candidate are then taken from the problem. The Jacobian is a forward
// difference in the box-normalised coordinates z = (x - lower) / range,
// one evaluation per parameter; candidates are clamped into the box.
#include "framework/core/eigen.hpp"
#include <string>

#include "framework/core/evaluation_context.hpp"
#include "framework/core/problem.hpp"

namespace hystbench {

// Minimises from x0 for at most `max_evaluations` evaluations (never past
// ctx's budget). Returns why it ended: "converged", "budget" or
// "no progress" (MINPACK found no step that lowers the SSE).
std::string run_levenberg_marquardt(EvaluationContext& ctx, const LeastSquaresProblem& problem,
                                    const Eigen::VectorXd& x0, long max_evaluations);

}  // namespace hystbench
