#include "framework/svr/svr_run.hpp"

#include <chrono>
#include <cmath>
#include <omp.h>

#include "framework/core/error.hpp"
#include "framework/discovery/data_source.hpp"
#include "framework/harness/trial_runner.hpp"

namespace hystbench {
namespace {

SvrResults::Search tune(const SvrExperiment& x, int threads) {
  TrialResult r = run_trial(*x.search_problem, x.search, 0, 0, threads);
  if (r.failed() || r.best_x.size() != 3 || !std::isfinite(r.best))
    throw InputError(x.name + ": the hyperparameter search found no finite fitness" +
                     (r.message.empty() ? "" : " (" + r.message + ")") +
                     "; widen the search box or give more evaluations");
  const auto h = SvrHyperparameters::from_log10(r.best_x[0], r.best_x[1], r.best_x[2]);
  return {std::move(r), h};
}

// The grey-box model's output over each whole test record (it carries its
// state from one test signal to the next, as the record was measured).
std::vector<Eigen::VectorXd> greybox_outputs(const SvrExperiment& x) {
  std::vector<Eigen::VectorXd> out;
  if (!x.greybox) return out;
  HoldoutSpec none;
  none.mode = HoldoutSpec::Mode::None;
  for (const SvrRecord& r : x.tests) {
    Eigen::VectorXd y;
    if (!simulate_physical(x.greybox->model, x.greybox->x, prepare_model_data(r.data, x.greybox->scales, none), y))
      throw InputError(x.greybox_path + ": the grey-box model diverges on " + r.name);
    out.push_back(std::move(y));
  }
  return out;
}

SvrTestRow test_row(const SvrExperiment& x, const SvrHammerstein& model, const SvrTestSignal& s,
                    const std::vector<Eigen::VectorXd>& greybox) {
  const Measurement& m = x.tests[s.record].data;
  const Eigen::Index n = s.end - s.begin;
  SvrTestRow row;
  row.signal = &s;
  row.scored_from = Eigen::Index(std::ceil(x.discard * double(n)));
  row.u = m.u.segment(s.begin, n);
  row.y = m.y.segment(s.begin, n);
  row.y_svr = model.simulate(row.u, row.y);
  row.svr = score(row.y, row.y_svr, model.one_step(row.u, row.y), row.scored_from);
  if (!greybox.empty()) {
    // An output-error model has no measured output to predict from: its
    // one-step prediction is its simulation.
    row.y_greybox = greybox[s.record].segment(s.begin, n);
    row.greybox = score(row.y, row.y_greybox, row.y_greybox, row.scored_from);
  }
  return row;
}

}  // namespace

SignalScore score(const Eigen::VectorXd& y, const Eigen::VectorXd& model, const Eigen::VectorXd& one_step,
                  Eigen::Index from) {
  const Eigen::Index n = y.size() - from;
  const Eigen::VectorXd e = model.tail(n) - y.tail(n);
  return {std::sqrt(e.squaredNorm() / double(n)), std::sqrt(e.squaredNorm() / y.tail(n).squaredNorm()),
          e.cwiseAbs().maxCoeff(), std::sqrt((one_step.tail(n) - y.tail(n)).squaredNorm() / double(n))};
}

SvrResults run_svr(const SvrExperiment& x, int threads, const std::function<void(const std::string&)>& status) {
  const auto start = std::chrono::steady_clock::now();
  if (!x.fixed)
    status("tuning epsilon, C, sigma (" + x.search.algorithms[0].label + ", " +
           std::to_string(x.search.budget.evaluations.value_or(0)) + " evaluations)");
  SvrResults::Search search = x.fixed ? SvrResults::Search{{}, *x.fixed} : tune(x, threads);
  status("training stage 1 on " + x.stage1.name);
  SvrHammerstein model = SvrHammerstein::fit_stage1(x.stage1.data.u, x.stage1.data.y, x.lags,
                                                    search.hyperparameters, x.name + ".stage1", x.train_rows);
  ArxSelection arx;
  if (x.stage2) {
    status("choosing the ARX orders on " + x.stage2->name);
    arx = model.fit_stage2(x.stage2->data.u, x.stage2->data.y, x.p_max, x.q_max, x.name + ".stage2",
                           x.coupling);
  }
  status("scoring " + std::to_string(x.signals.size()) + " test signals");
  const auto greybox = greybox_outputs(x);
  std::vector<SvrTestRow> rows(x.signals.size());
#pragma omp parallel for schedule(dynamic) num_threads(threads)
  for (std::size_t i = 0; i < rows.size(); ++i) rows[i] = test_row(x, model, x.signals[i], greybox);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return {std::move(search), std::move(model), std::move(arx), std::move(rows), seconds};
}

}  // namespace hystbench
