// Uniform random search: the smallest useful optimizer plugin.
#include "framework/core/registry.hpp"

namespace {
class RandomSearch : public hystbench::Optimizer {
 public:
  static hystbench::OptimizerInfo info() {
    return {"random_search", "uniform random sampling", "(baseline)",
            {hystbench::ParamSpec::integer("batch", 64, 1, 100000, "points per batch")}};
  }
  explicit RandomSearch(const hystbench::Params& p) : batch_(p.integer("batch")) {}

  void run(hystbench::EvaluationContext& ctx) override {
    const auto& b = ctx.bounds();
    Eigen::MatrixXd X(ctx.dimension(), batch_);
    Eigen::VectorXd f;
    while (ctx.next_iteration()) {
      for (int i = 0; i < batch_; ++i)
        for (int j = 0; j < ctx.dimension(); ++j) X(j, i) = ctx.rng().uniform(b.lower[j], b.upper[j]);
      ctx.evaluate(X, f);  // the context counts, stops, and keeps the best
    }
  }

 private:
  int batch_;
};
}  // namespace

HYSTBENCH_OPTIMIZER(RandomSearch)
