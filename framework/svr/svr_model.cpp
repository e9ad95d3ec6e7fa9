#include "framework/svr/svr_model.hpp"

#include <algorithm>
#include <cmath>

#include "framework/core/error.hpp"

namespace hystbench {
namespace {

Eigen::VectorXd to_unit(const Eigen::VectorXd& v, const MinMaxScale& s) {
  return v.unaryExpr([&](double e) { return s.to_unit(e); });
}

// Row for predicting sample k+1: x(k..k-m), w(k..k-n) [, r(k)], from scaled
// series; `rate_step` scales the rate regressor.
void fill_row(const Eigen::VectorXd& xs, const Eigen::VectorXd& ws, Eigen::Index k, const SvrLags& lags,
              double rate_step, Eigen::Ref<Eigen::VectorXd> row) {
  for (int i = 0; i <= lags.m; ++i) row[i] = xs[k - i];
  for (int i = 0; i <= lags.n; ++i) row[lags.m + 1 + i] = ws[k - i];
  if (lags.input_rate) row[lags.m + lags.n + 2] = rate_regressor(xs[k - 1], xs[k], rate_step);
}

// The largest step of a scaled input, so that the training record's rates
// fill tanh's steep part; 1 when the model has no rate regressor.
double rate_step_of(const Eigen::VectorXd& xs, const SvrLags& lags) {
  if (!lags.input_rate || xs.size() < 2) return 1.0;
  const double step = (xs.tail(xs.size() - 1) - xs.head(xs.size() - 1)).cwiseAbs().maxCoeff();
  return step > 0.0 ? step : 1.0;
}

nlohmann::json arx_json(const ArxFit& f) {
  return {{"p", f.p}, {"q", f.q}, {"a", std::vector<double>(f.a.begin(), f.a.end())},
          {"b", std::vector<double>(f.b.begin(), f.b.end())}, {"aic", f.aic}};
}

}  // namespace

MinMaxScale MinMaxScale::of(const Eigen::VectorXd& x) { return {x.minCoeff(), x.maxCoeff()}; }

void SvrHammerstein::regression_rows(const Eigen::VectorXd& x, const Eigen::VectorXd& y, const SvrLags& lags,
                                     Eigen::MatrixXd& rows, Eigen::VectorXd& targets) {
  const Eigen::VectorXd xs = to_unit(x, MinMaxScale::of(x)), ys = to_unit(y, MinMaxScale::of(y));
  const Eigen::Index first = lags.warmup() - 1, count = ys.size() - 1 - first;
  const double rate_step = rate_step_of(xs, lags);
  rows.resize(std::max<Eigen::Index>(count, 0), lags.dimension());
  targets.resize(rows.rows());
  Eigen::VectorXd row(rows.cols());
  for (Eigen::Index r = 0; r < rows.rows(); ++r) {
    const Eigen::Index k = first + r;
    fill_row(xs, ys, k, lags, rate_step, row);
    rows.row(r) = row.transpose();
    targets[r] = ys[k + 1];
  }
}

void SvrHammerstein::decimate(Eigen::MatrixXd& rows, Eigen::VectorXd& targets, Eigen::Index most) {
  if (rows.rows() <= most) return;
  const Eigen::Index step = (rows.rows() + most - 1) / most, kept = (rows.rows() + step - 1) / step;
  Eigen::MatrixXd r(kept, rows.cols());
  Eigen::VectorXd t(kept);
  for (Eigen::Index i = 0; i < kept; ++i) {
    r.row(i) = rows.row(i * step);
    t[i] = targets[i * step];
  }
  rows = std::move(r);
  targets = std::move(t);
}

SvrHammerstein SvrHammerstein::fit_stage1(const Eigen::VectorXd& x, const Eigen::VectorXd& y,
                                          const SvrLags& lags, const SvrHyperparameters& h,
                                          const std::string& where, Eigen::Index max_rows) {
  if (x.size() != y.size() || y.size() < lags.warmup() + 2)
    throw InputError(where + ": stage 1 with lags m = " + std::to_string(lags.m) + ", n = " +
                     std::to_string(lags.n) + " needs at least " + std::to_string(lags.warmup() + 2) +
                     " samples of x and y, got " + std::to_string(x.size()) + " and " +
                     std::to_string(y.size()));
  const MinMaxScale xs = MinMaxScale::of(x), ys = MinMaxScale::of(y);
  if (!(xs.hi > xs.lo) || !(ys.hi > ys.lo))
    throw InputError(where + ": the input or the output is constant; stage 1 needs both to vary");
  Eigen::MatrixXd rows;
  Eigen::VectorXd targets;
  regression_rows(x, y, lags, rows, targets);
  if (max_rows > 0) decimate(rows, targets, max_rows);
  return SvrHammerstein(SvrRegressor::train(rows, targets, h, where), lags, xs, ys,
                        rate_step_of(to_unit(x, xs), lags));
}

ArxSelection SvrHammerstein::fit_stage2(const Eigen::VectorXd& x, const Eigen::VectorXd& y, int p_max,
                                        int q_max, const std::string& where, SvrCoupling coupling) {
  arx_.reset();  // stage 2 sees stage 1 alone
  const Eigen::VectorXd w = coupling == SvrCoupling::FreeRun ? stage1_free_run(x, y) : one_step(x, y);
  ArxSelection s = select_arx(w, y, p_max, q_max, where);
  arx_ = s.best;
  return s;
}

Eigen::VectorXd SvrHammerstein::one_step(const Eigen::VectorXd& x, const Eigen::VectorXd& y) const {
  const Eigen::VectorXd xs = to_unit(x, x_scale_), ys = to_unit(y, y_scale_);
  Eigen::VectorXd out = y;
  Eigen::VectorXd row(lags_.dimension());
  for (Eigen::Index k = lags_.warmup() - 1; k + 1 < y.size(); ++k) {
    fill_row(xs, ys, k, lags_, rate_step_, row);
    out[k + 1] = y_scale_.from_unit(svr_.predict(row));
  }
  return out;
}

Eigen::VectorXd SvrHammerstein::stage1_free_run(const Eigen::VectorXd& x, const Eigen::VectorXd& y) const {
  const Eigen::VectorXd xs = to_unit(x, x_scale_);
  Eigen::VectorXd ws = Eigen::VectorXd::Zero(x.size());
  const Eigen::Index warm = std::min<Eigen::Index>(lags_.warmup(), x.size());
  ws.head(warm) = to_unit(y.head(warm), y_scale_);
  Eigen::VectorXd row(lags_.dimension());
  for (Eigen::Index k = warm - 1; k + 1 < x.size(); ++k) {
    fill_row(xs, ws, k, lags_, rate_step_, row);
    ws[k + 1] = svr_.predict(row);
  }
  return ws.unaryExpr([&](double s) { return y_scale_.from_unit(s); });
}

Eigen::VectorXd SvrHammerstein::simulate(const Eigen::VectorXd& x, const Eigen::VectorXd& y_start) const {
  const Eigen::VectorXd w = stage1_free_run(x, y_start);
  return arx_ ? arx_->simulate(w) : w;
}

std::string SvrHammerstein::describe() const {
  return "svr_hammerstein(m = " + std::to_string(lags_.m) + ", n = " + std::to_string(lags_.n) +
         (lags_.input_rate ? ", input rate" : "") +
         (arx_ ? ", ARX " + std::to_string(arx_->p) + "/" + std::to_string(arx_->q) : std::string(", no ARX")) + ")";
}

nlohmann::json SvrHammerstein::to_json() const {
  nlohmann::json j = {{"model", "svr_hammerstein"},
                      {"lags", {{"m", lags_.m}, {"n", lags_.n}}},
                      {"input_scale", {{"min", x_scale_.lo}, {"max", x_scale_.hi}}},
                      {"output_scale", {{"min", y_scale_.lo}, {"max", y_scale_.hi}}},
                      {"svr", svr_.to_json()}};
  if (lags_.input_rate) {
    j["lags"]["input_rate"] = true;
    j["rate_step"] = rate_step_;
  }
  if (arx_) j["arx"] = arx_json(*arx_);
  return j;
}

SvrHammerstein SvrHammerstein::from_json(const nlohmann::json& j, const std::string& where) {
  try {
    if (j.value("model", "") != "svr_hammerstein")
      throw InputError(where + ".model: not \"svr_hammerstein\"; this is not an SVR model file");
    const SvrLags lags{j.at("lags").at("m").get<int>(), j.at("lags").at("n").get<int>(),
                       j.at("lags").value("input_rate", false)};
    if (lags.m < 0 || lags.n < 0 || lags.m > 50 || lags.n > 50)
      throw InputError(where + ".lags: m and n must be from 0 to 50");
    const MinMaxScale xs{j.at("input_scale").at("min").get<double>(), j.at("input_scale").at("max").get<double>()};
    const MinMaxScale ys{j.at("output_scale").at("min").get<double>(),
                         j.at("output_scale").at("max").get<double>()};
    SvrRegressor svr = SvrRegressor::from_json(j.at("svr"), where + ".svr");
    if (svr.dimension() != lags.dimension())
      throw InputError(where + ".svr.dimension: " + std::to_string(svr.dimension()) +
                       " does not match the lags (m + n + 2" + (lags.input_rate ? " + 1 for the rate" : "") +
                       " = " + std::to_string(lags.dimension()) + ")");
    const double rate_step = lags.input_rate ? j.at("rate_step").get<double>() : 1.0;
    if (!(rate_step > 0.0) || !std::isfinite(rate_step))
      throw InputError(where + ".rate_step: must be a positive finite number");
    SvrHammerstein model(std::move(svr), lags, xs, ys, rate_step);
    if (j.contains("arx")) {
      const auto& a = j["arx"];
      ArxFit f;
      f.p = a.at("p").get<int>();
      f.q = a.at("q").get<int>();
      const auto av = a.at("a").get<std::vector<double>>(), bv = a.at("b").get<std::vector<double>>();
      f.a = Eigen::Map<const Eigen::VectorXd>(av.data(), Eigen::Index(av.size()));
      f.b = Eigen::Map<const Eigen::VectorXd>(bv.data(), Eigen::Index(bv.size()));
      f.aic = a.value("aic", 0.0);
      f.stable = true;
      if (f.a.size() != f.p || f.b.size() != f.q)
        throw InputError(where + ".arx: a and b must have p and q coefficients");
      model.arx_ = f;
    }
    return model;
  } catch (const nlohmann::json::exception& e) {
    throw InputError(where + ": not an SVR model (" + std::string(e.what()) + ")");
  }
}

}  // namespace hystbench
