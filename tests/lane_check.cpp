// Whether an effect loaded from a plugin evaluates a block of candidates
// exactly as it evaluates them one at a time, and has a batched form at all:
// a generated effect (hystbench propose) must, to fit as fast as the
// catalog's (tests/beyond_catalog.sh).
//
//   hystbench_lane_check PLUGIN.so MODEL
//
// Exit 0 when the model is batched and every one of 19 candidates across its
// box (neutral, on the bounds, invalid) gives the same SSE both ways; 1
// otherwise, naming the first candidate that differs.
#include <cmath>
#include <iostream>

#include "framework/core/plugin_loader.hpp"
#include "framework/model/model_problem.hpp"
#include "tests/lane_record.hpp"

int main(int argc, char** argv) {
  using namespace hystbench;
  if (argc != 3) {
    std::cerr << "usage: hystbench_lane_check PLUGIN.so MODEL\n";
    return 2;
  }
  load_plugin(argv[1]);
  const Model model = Model::parse(argv[2]);
  const ModelData data = lane_record();
  const ModelProblem problem(model, data);
  if (!problem.batched()) {
    std::cerr << argv[2] << ": no batched form; candidates are evaluated one at a time\n";
    return 1;
  }
  const Eigen::MatrixXd X = lane_candidates(model, 19, 7);
  Eigen::VectorXd f(X.cols());
  problem.evaluate(X, f);
  int finite = 0;
  for (Eigen::Index j = 0; j < X.cols(); ++j) {
    const double one = problem.sse(X.col(j));
    if (!(f[j] == one) && !(std::isinf(f[j]) && std::isinf(one))) {
      std::cerr << argv[2] << ": candidate " << j << " gives " << f[j] << " in a block and " << one << " alone\n";
      return 1;
    }
    finite += std::isfinite(one);
  }
  std::cout << argv[2] << ": " << X.cols() << " candidates, " << finite << " finite, equal in blocks and alone\n";
  return finite > 0 ? 0 : 1;
}
