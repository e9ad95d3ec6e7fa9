#include "framework/discovery/ladder.hpp"

namespace hystbench {
namespace {

LadderStep make_step(const Model& model, const Eigen::VectorXd& x, const ModelData& data,
                     const std::string& added, const std::string& evidence) {
  LadderStep s{model, x, fit_errors(model, x, data)};
  s.bic = bic(s.errors.sse, s.errors.n_estimation, model.dimension());
  s.added = added;
  s.evidence = evidence;
  return s;
}

}  // namespace

Ladder discover(const Model& start, const ModelData& data, const DiscoverOptions& o,
                const std::function<void(const LadderStep&, const Diagnosis&)>& on_step) {
  Ladder ladder;
  const FitResult first = fit_model(start, data, o.diagnose.fit);
  Model model = first.model;
  Eigen::VectorXd x = first.x;
  std::string added, evidence;
  for (int step = 0;; ++step) {
    Diagnosis d = diagnose(model, x, data, o.diagnose);
    // The diagnosis polished the fit once more: that polished fit is the rung.
    ladder.steps.push_back(make_step(d.model, d.x, data, added, evidence));
    ladder.steps.back().where = d.where;
    if (on_step) on_step(ladder.steps.back(), d);
    const bool has_winner = d.winner() != nullptr;
    ladder.diagnoses.push_back(std::move(d));
    if (!has_winner) break;
    if (step == o.max_steps) {
      ladder.stopped_by_limit = true;
      break;
    }
    FitOptions refit = o.diagnose.fit;
    refit.restarts = o.refit_restarts;
    refit.seed = o.diagnose.fit.seed + std::uint64_t(step) + 1;
    const Candidate& w = *ladder.diagnoses.back().winner();
    const FitResult r = fit_model(w.model, data, refit, &w.x);
    model = r.model;
    x = r.x;
    added = w.effect;
    evidence = w.evidence;
  }
  return ladder;
}

}  // namespace hystbench
