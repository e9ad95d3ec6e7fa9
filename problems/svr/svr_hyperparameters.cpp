#include "problems/svr/svr_hyperparameters.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <map>

#include "framework/core/error.hpp"
#include "framework/core/parameters.hpp"
#include "framework/svr/svr_record.hpp"
#include "framework/svr/svr_validation.hpp"

namespace hystbench {
namespace {

void add_bound(const Params& p, const std::string& key, Bounds& b) {
  const auto [lo, hi] = p.range(key);
  const Eigen::Index i = b.lower.size();
  b.lower.conservativeResize(i + 1);
  b.upper.conservativeResize(i + 1);
  b.lower[i] = lo;
  b.upper[i] = hi;
  b.names.push_back(key);
}

double mean_squared(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return (a - b).squaredNorm() / double(a.size());
}

}  // namespace

ProblemInfo SvrHyperparameterProblem::info() {
  return {"svr_hyperparameters",
          "epsilon, C and sigma of the SVR model's stage 1 (log10 box), fitness = validation "
          "error of the one-step prediction (blocked CV, libsvm CV or free-run hold-out)",
          {ParamSpec::text("data", nullptr,
                           "the training record (CSV with t, u, y), e.g. the 1 Hz record")
               .require(),
           ParamSpec::text("segment", "", "the segment of the record to train on; empty = all"),
           ParamSpec::object("columns", "column names of t, u, y in the CSV"),
           ParamSpec::object("lags", "stage 1's regressors {\"m\": 4, \"n\": 4, \"input_rate\": false}"),
           ParamSpec::choice("fitness", "blocked_cv", {"blocked_cv", "libsvm_cv", "freerun_holdout"},
                             "validation error of the one-step prediction"),
           ParamSpec::integer("folds", 5, 2, 100, "cross-validation folds"),
           ParamSpec::real("holdout", 0.25, 0.05, 0.9, "share of the record held out (freerun_holdout)"),
           ParamSpec::integer("cv_seed", 1, 0, 4294967295.0, "seed of libsvm's fold assignment"),
           ParamSpec::integer("max_rows", 1000, 10, 1e7, "regression rows kept (decimated)"),
           // Where libsvm answers in about a second at most (docs/svr.md#hyperparameters).
           ParamSpec::range("log10_epsilon", -3, -1, "search interval of log10 epsilon"),
           ParamSpec::range("log10_C", -1, 3, "search interval of log10 C"),
           ParamSpec::range("log10_sigma", 1, 3, "search interval of log10 sigma")},
          [](const Params& p, const std::filesystem::path& base_dir) {
            return std::unique_ptr<Problem>(new SvrHyperparameterProblem(p, base_dir));
          }};
}

SvrHyperparameterProblem::SvrHyperparameterProblem(const Params& p,
                                                   const std::filesystem::path& base_dir) {
  const ColumnMap columns =
      p.is_auto("columns") ? ColumnMap{} : ColumnMap::from_json(p.value("columns"), "problem.columns");
  const SvrRecord record = read_svr_record(p.text("data"), p.text("segment"), columns, base_dir, "problem");
  data_name_ = record.name;
  x_ = record.data.u;
  y_ = record.data.y;
  const Params lags = validate_params({ParamSpec::integer("m", 4, 0, 50, "input lags"),
                                       ParamSpec::integer("n", 4, 0, 50, "output lags"),
                                       ParamSpec::boolean("input_rate", false, "the input's rate as a regressor")},
                                      p.value("lags"), "problem.lags");
  lags_ = {lags.integer("m"), lags.integer("n"), lags.boolean("input_rate")};
  const std::map<std::string, Fitness> fitness = {
      {"blocked_cv", Fitness::BlockedCv}, {"libsvm_cv", Fitness::LibsvmCv}, {"freerun_holdout", Fitness::FreerunHoldout}};
  fitness_ = fitness.at(p.text("fitness"));  // the choices the spec allows
  folds_ = p.integer("folds");
  holdout_ = p.real("holdout");
  cv_seed_ = unsigned(p.real("cv_seed"));
  if (y_.size() < lags_.warmup() + 2 * folds_)
    throw InputError(data_name_ + ": " + std::to_string(y_.size()) + " samples are too few for lags m = " +
                     std::to_string(lags_.m) + ", n = " + std::to_string(lags_.n) + " and " +
                     std::to_string(folds_) + " folds");
  SvrHammerstein::regression_rows(x_, y_, lags_, rows_, targets_);
  max_rows_ = Eigen::Index(p.integer("max_rows"));
  SvrHammerstein::decimate(rows_, targets_, max_rows_);
  for (const char* key : {"log10_epsilon", "log10_C", "log10_sigma"}) add_bound(p, key, bounds_);
  // Every corner of the box must be a valid SVR, checked before any search.
  for (int corner = 0; corner < 8; ++corner) {
    auto at = [&](int i) { return (corner >> i) & 1 ? bounds_.upper[i] : bounds_.lower[i]; };
    SvrRegressor::check(SvrHyperparameters::from_log10(at(0), at(1), at(2)), "problem (the box's corner)");
  }
}

std::string SvrHyperparameterProblem::name() const { return "svr_hyperparameters(" + data_name_ + ")"; }

double SvrHyperparameterProblem::blocked_cv(const SvrHyperparameters& h) const {
  return blocked_cv_error(rows_, targets_, h, folds_);
}

double SvrHyperparameterProblem::libsvm_cv(const SvrHyperparameters& h) const {
  return mean_squared(SvrRegressor::libsvm_cross_validation(rows_, targets_, h, folds_, cv_seed_, "problem"),
                      targets_);
}

double SvrHyperparameterProblem::freerun_holdout(const SvrHyperparameters& h) const {
  const Eigen::Index cut = Eigen::Index(double(y_.size()) * (1.0 - holdout_));
  const SvrHammerstein model = SvrHammerstein::fit_stage1(x_.head(cut), y_.head(cut), lags_, h, "problem", max_rows_);
  // The held-out part in free run, started from its own first samples.
  const Eigen::VectorXd x = x_.tail(y_.size() - cut), y = y_.tail(y_.size() - cut);
  const double range = y_.maxCoeff() - y_.minCoeff();
  return mean_squared(model.simulate(x, y) / (0.5 * range), y / (0.5 * range));
}

double SvrHyperparameterProblem::fitness(const SvrHyperparameters& h) const {
  switch (fitness_) {
    case Fitness::BlockedCv: return blocked_cv(h);
    case Fitness::LibsvmCv: return libsvm_cv(h);
    case Fitness::FreerunHoldout: return freerun_holdout(h);
  }
  return std::numeric_limits<double>::infinity();
}

void SvrHyperparameterProblem::evaluate(const Eigen::Ref<const Eigen::MatrixXd>& X,
                                        Eigen::Ref<Eigen::VectorXd> f) const {
  evaluate_with(X, f, {});
}

void SvrHyperparameterProblem::evaluate_with(const Eigen::Ref<const Eigen::MatrixXd>& X,
                                             Eigen::Ref<Eigen::VectorXd> f,
                                             const EvaluationOptions& options) const {
  // An exception may not leave an OpenMP region: the first is kept and
  // rethrown after it, as the serial loop would have thrown it.
  std::exception_ptr error;
#pragma omp parallel for schedule(dynamic) num_threads(std::max(1, options.threads))
  for (Eigen::Index i = 0; i < X.cols(); ++i) {
    try {
      f[i] = fitness(SvrHyperparameters::from_log10(X(0, i), X(1, i), X(2, i)));
    } catch (...) {
#pragma omp critical(svr_hyperparameters_error)
      if (!error) error = std::current_exception();
    }
  }
  if (error) std::rethrow_exception(error);
}

nlohmann::json SvrHyperparameterProblem::describe() const {
  const char* names[] = {"blocked_cv", "libsvm_cv", "freerun_holdout"};
  return {{"name", name()},
          {"fitness", std::string("MSE, ") + names[int(fitness_)]},
          {"data", data_name_},
          {"lags", {{"m", lags_.m}, {"n", lags_.n}, {"input_rate", lags_.input_rate}}},
          {"rows", rows_.rows()},
          {"folds", folds_},
          {"parameters", bounds_.names}};
}

}  // namespace hystbench

HYSTBENCH_PROBLEM(hystbench::SvrHyperparameterProblem)
