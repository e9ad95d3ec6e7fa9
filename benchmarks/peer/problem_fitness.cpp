#include "benchmarks/peer/problem_fitness.hpp"

namespace hystbench::peer {

BoxFitness box_fitness(const Problem& problem) {
  const Bounds& b = problem.bounds();
  const Eigen::Index n = b.dimension();
  BoxFitness box;
  box.lower.assign(b.lower.begin(), b.lower.end());
  box.upper.assign(b.upper.begin(), b.upper.end());
  // Candidates one after another are the columns of a column-major matrix.
  box.evaluate = [&problem, n](const double* x, std::size_t count, double* f) {
    const auto cols = static_cast<Eigen::Index>(count);
    problem.evaluate(Eigen::Map<const Eigen::MatrixXd>(x, n, cols), Eigen::Map<Eigen::VectorXd>(f, cols));
  };
  return box;
}

}  // namespace hystbench::peer
