#include "framework/discovery/ladder.hpp"

#include <exception>
#include <optional>
#include <utility>

namespace hystbench {
namespace {

struct Pruned {
  FitResult fit;
  std::vector<std::string> removed;
};

// One round of backward elimination: the best removal if it lowers the BIC.
std::optional<std::pair<std::string, FitResult>> best_removal(const FitResult& current,
                                                             const std::string& keep,
                                                             const ModelData& data,
                                                             const FitOptions& fit) {
  const long n = data.estimation_count();
  const double current_bic = bic(current.sse, n, current.model.dimension());
  const auto effects = current.model.effects();
  std::vector<std::optional<FitResult>> tried(effects.size());
  std::vector<std::exception_ptr> failed(effects.size());
#pragma omp parallel for schedule(dynamic)
  for (std::size_t i = 0; i < effects.size(); ++i) {
    if (effects[i] == keep) continue;
    try {  // an exception must not leave an OpenMP region
      const Model smaller = current.model.without(effects[i]);
      tried[i] = refit_warm(smaller, data, smaller.carry_over(current.model, current.x), {}, fit);
    } catch (...) {
      failed[i] = std::current_exception();
    }
  }
  for (const auto& e : failed)
    if (e) std::rethrow_exception(e);
  std::optional<std::pair<std::string, FitResult>> best;
  double best_bic = current_bic;
  for (std::size_t i = 0; i < effects.size(); ++i) {
    if (!tried[i]) continue;
    const double b = bic(tried[i]->sse, n, tried[i]->model.dimension());
    if (b < best_bic) best_bic = b, best.emplace(effects[i], *tried[i]);
  }
  return best;
}

Pruned prune(FitResult current, const std::string& keep, const ModelData& data,
             const FitOptions& fit) {
  Pruned p{std::move(current), {}};
  while (auto removal = best_removal(p.fit, keep, data, fit)) {
    if (fit.status) fit.status("pruned " + removal->first);
    p.removed.push_back(removal->first);
    p.fit = std::move(removal->second);
  }
  return p;
}

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
  std::vector<std::string> removed;
  for (int step = 0;; ++step) {
    Diagnosis d = diagnose(model, x, data, o.diagnose);
    // The diagnosis polished the fit once more: that polished fit is the rung.
    ladder.steps.push_back(make_step(d.model, d.x, data, added, evidence));
    ladder.steps.back().where = d.where;
    ladder.steps.back().removed = removed;
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
    Pruned p = prune(fit_model(w.model, data, refit, &w.x), w.effect, data, refit);
    if (!p.removed.empty()) p.fit = fit_model(p.fit.model, data, refit, &p.fit.x);
    model = p.fit.model;
    x = p.fit.x;
    removed = p.removed;
    added = w.effect;
    evidence = w.evidence;
  }
  return ladder;
}

}  // namespace hystbench
