#include "framework/stats/forward_regression.hpp"

#include "framework/core/eigen.hpp"
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace hystbench {
namespace {

// Below this share of its own norm a column is a combination of the chosen ones.
constexpr double kCollinear = 1e-10;
// A share of the target's sum of squares below which nothing is left.
constexpr double kNothingLeft = 1e-12;
// ERRs this close (relative) are a tie.
constexpr double kTie = 1e-9;
// Check residuals this close (relative) are a tie. Looser: a residual left
// by a good column is small, so the rounding of two columns that are the
// same term through two paths (finite differences of a 1e−6 probe, in
// propose) shows in it far more than in their ERRs.
constexpr double kCheckTie = 1e-6;

struct Scores {
  ForwardStep best, second;
};

// The check rows of the columns as they are orthogonalised on the fit rows
// (every operation on a column of Q applied to its check rows), and of the
// residual the columns taken leave there: the check residual with one more
// column j is left − g_j·Q_j, g_j its coefficient on the fit rows, with no
// refit per candidate.
struct CheckColumns {
  Eigen::MatrixXd Q;
  Eigen::VectorXd left;
  Eigen::MatrixXd fixed;
};

// ERR of column j of Q against the target left (sum of squares ee); 0 for
// a column that is a combination of those taken.
double err_of(const Eigen::MatrixXd& Q, Eigen::Index j, const Eigen::VectorXd& own_norm2, const Eigen::VectorXd& e,
              double ee) {
  const double qq = Q.col(j).squaredNorm();
  if (!(qq > kCollinear * own_norm2[j])) return 0.0;
  const double qe = Q.col(j).dot(e);
  return qe * qe / (qq * ee);
}

// The best and second-best remaining columns by ERR.
Scores score(const Eigen::MatrixXd& Q, const Eigen::VectorXd& own_norm2, const std::vector<bool>& taken,
             const Eigen::VectorXd& e, double ee) {
  Scores s;
  for (Eigen::Index j = 0; j < Q.cols(); ++j) {
    if (taken[std::size_t(j)]) continue;
    const double err = err_of(Q, j, own_norm2, e, ee);
    if (!(err > 0.0)) continue;
    // A column equal to the best one up to rounding (the same term entering
    // through an identical path) does not displace it: the earlier wins.
    if (err > s.best.err * (1.0 + kTie)) {
      s.second = s.best;
      s.best = {int(j), err};
    } else if (err > s.second.err) {
      s.second = {int(j), err};
    }
  }
  return s;
}

double bic_change(double err, double explained, double n) {
  const double tiny = std::numeric_limits<double>::min();
  const double left = std::max(1.0 - explained, tiny);
  return n * std::log(std::max(1.0 - err / left, tiny)) + std::log(n);
}

// Among the columns whose ERR passes the BIC rule, the best and second-best
// by the check residual they leave (check_rms), so that a column which
// explains the fit rows' noise does not outrank one that holds on samples
// the fit never saw. When no column passes, the best by ERR: the BIC rule
// then refuses it.
Scores score_heldout(const Eigen::MatrixXd& Q, const Eigen::VectorXd& own_norm2, const std::vector<bool>& taken,
                     const Eigen::VectorXd& e, double ee, double explained, const CheckColumns& check,
                     double bic_threshold) {
  Scores s;
  double best_ss = std::numeric_limits<double>::infinity(), second_ss = best_ss;
  const double n = double(e.size()), nc = double(check.left.size());
  for (Eigen::Index j = 0; j < Q.cols(); ++j) {
    if (taken[std::size_t(j)]) continue;
    const double err = err_of(Q, j, own_norm2, e, ee);
    if (!(err > 0.0) || bic_change(err, explained, n) > bic_threshold) continue;
    const double g = Q.col(j).dot(e) / Q.col(j).squaredNorm();
    const double ss = (check.left - g * check.Q.col(j)).squaredNorm();
    const ForwardStep step{int(j), err, 0.0, std::sqrt(ss / nc)};
    if (ss < best_ss * (1.0 - kCheckTie)) {
      s.second = s.best, second_ss = best_ss;
      s.best = step, best_ss = ss;
    } else if (ss < second_ss) {
      s.second = step, second_ss = ss;
    }
  }
  return s.best.column >= 0 ? s : score(Q, own_norm2, taken, e, ee);
}

// The chosen columns of P beside the fixed ones.
Eigen::MatrixXd design(const RegressionRows& rows, const std::vector<int>& chosen) {
  Eigen::MatrixXd A(rows.P.rows(), Eigen::Index(chosen.size()) + rows.fixed.cols());
  for (std::size_t i = 0; i < chosen.size(); ++i) A.col(Eigen::Index(i)) = rows.P.col(chosen[i]);
  if (rows.fixed.cols() > 0) A.rightCols(rows.fixed.cols()) = rows.fixed;
  return A;
}

// Least squares of e on the chosen and fixed columns.
Eigen::VectorXd least_squares(const RegressionRows& rows, const std::vector<int>& chosen) {
  const Eigen::MatrixXd A = design(rows, chosen);
  if (A.cols() == 0) return {};
  return Eigen::ColPivHouseholderQR<Eigen::MatrixXd>(A).solve(rows.e);
}

double rms_residual(const RegressionRows& rows, const std::vector<int>& chosen, const Eigen::VectorXd& theta) {
  if (rows.e.size() == 0) return 0.0;
  const Eigen::VectorXd r = theta.size() ? Eigen::VectorXd(rows.e - design(rows, chosen) * theta) : rows.e;
  return std::sqrt(r.squaredNorm() / double(r.size()));
}

// Coefficients and standard errors of the final choice.
void fit_chosen(const RegressionRows& fit, const std::vector<int>& chosen, ForwardRegression& r) {
  const Eigen::Index k = Eigen::Index(chosen.size());
  const Eigen::MatrixXd A = design(fit, chosen);
  const Eigen::VectorXd theta = least_squares(fit, chosen);
  r.coefficients = theta.head(k);
  r.fixed_coefficients = theta.tail(fit.fixed.cols());
  r.standard_errors = Eigen::VectorXd::Zero(k);
  if (k == 0) return;
  const double dof = std::max<double>(1.0, double(A.rows() - A.cols()));
  const double s2 = (fit.e - A * theta).squaredNorm() / dof;
  // Columns scaled to unit norm first: the sensitivities and the terms
  // differ by orders of magnitude, and AᵀA squares that.
  const Eigen::VectorXd norm = A.colwise().norm().transpose().cwiseMax(std::numeric_limits<double>::min());
  const Eigen::MatrixXd scaled = A * norm.cwiseInverse().asDiagonal();
  const Eigen::VectorXd variance = (scaled.transpose() * scaled).inverse().diagonal() * s2;
  r.standard_errors = (variance.array().sqrt() / norm.array()).head(k);
}

// Removes from every column of Q and from e their part in the span of
// `fixed`, and from the check rows the same combinations of their own fixed
// columns, so that they stay the check rows of the same columns.
void project_out(const Eigen::MatrixXd& fixed, Eigen::MatrixXd& Q, Eigen::VectorXd& e, CheckColumns* check) {
  if (fixed.cols() == 0) return;
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(fixed);
  const Eigen::MatrixXd B = qr.solve(Q);
  const Eigen::VectorXd b = qr.solve(e);
  Q -= fixed * B;
  e -= fixed * b;
  if (!check) return;
  check->Q -= check->fixed * B;
  check->left -= check->fixed * b;
}

// The fixed columns that are not combinations of others (a parameter at a
// value where it does nothing has a zero sensitivity), so that the final
// fit's covariance exists.
std::vector<Eigen::Index> independent_columns(const Eigen::MatrixXd& fixed) {
  std::vector<Eigen::Index> kept;
  if (fixed.cols() == 0) return kept;
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(fixed);
  qr.setThreshold(1e-10);
  for (Eigen::Index i = 0; i < qr.rank(); ++i) kept.push_back(qr.colsPermutation().indices()[i]);
  std::sort(kept.begin(), kept.end());
  return kept;
}

// The rows with only the independent fixed columns (`kept`).
RegressionRows with_fixed(const RegressionRows& rows, const std::vector<Eigen::Index>& kept) {
  RegressionRows out{rows.P, rows.e, Eigen::MatrixXd(rows.fixed.rows(), Eigen::Index(kept.size()))};
  for (std::size_t i = 0; i < kept.size(); ++i) out.fixed.col(Eigen::Index(i)) = rows.fixed.col(kept[i]);
  return out;
}

// Which rule refuses `step` after `taken` steps ("" when none does).
std::string refusal(const ForwardStep& step, std::size_t taken, double check_rms, bool checked,
                    const ForwardRegressionOptions& o) {
  if (int(taken) >= o.max_terms) return "max_terms";
  if (step.delta_bic > o.bic_threshold) return "bic";
  if (checked && step.check_rms > (1.0 - o.heldout_gain) * check_rms) return "heldout";
  return "";
}

// Modified Gram–Schmidt: every remaining column loses its part along column
// c, and its check rows the same multiple of c's.
void orthogonalise(Eigen::MatrixXd& Q, int c, const std::vector<bool>& taken, CheckColumns* check) {
  const Eigen::VectorXd q = Q.col(c);
  const Eigen::VectorXd qc = check ? Eigen::VectorXd(check->Q.col(c)) : Eigen::VectorXd();
  const double qq = q.squaredNorm();
  for (Eigen::Index j = 0; j < Q.cols(); ++j) {
    if (taken[std::size_t(j)]) continue;
    const double a = q.dot(Q.col(j)) / qq;
    Q.col(j) -= a * q;
    if (check) check->Q.col(j) -= a * qc;
  }
}

// The steps, on rows whose fixed columns are independent. With check rows,
// each step takes the column that lowers their residual most among those
// the BIC rule admits; without, the largest ERR.
void choose(const RegressionRows& fit, const RegressionRows* check, const ForwardRegressionOptions& options,
            ForwardRegression& r, std::vector<int>& chosen) {
  Eigen::MatrixXd Q = fit.P;
  Eigen::VectorXd left = fit.e;
  std::optional<CheckColumns> held;
  if (check) held = CheckColumns{check->P, check->e, check->fixed};
  project_out(fit.fixed, Q, left, held ? &*held : nullptr);
  const double ee = left.squaredNorm();
  r.fixed_share = fit.e.squaredNorm() > 0.0 ? 1.0 - ee / fit.e.squaredNorm() : 0.0;
  if (check) r.check_rms = rms_residual(*check, chosen, least_squares(fit, chosen));
  double check_rms = r.check_rms;
  const Eigen::VectorXd own_norm2 = fit.P.colwise().squaredNorm().transpose();
  std::vector<bool> taken(std::size_t(fit.P.cols()), false);
  r.first_err = Eigen::VectorXd::Zero(fit.P.cols());
  for (Eigen::Index j = 0; j < Q.cols() && ee > 0.0; ++j) r.first_err[j] = err_of(Q, j, own_norm2, left, ee);
  while (ee > 0.0) {
    const Scores s = held ? score_heldout(Q, own_norm2, taken, left, ee, r.explained, *held, options.bic_threshold)
                          : score(Q, own_norm2, taken, left, ee);
    ForwardStep step = s.best;
    step.runner_up = s.second.column;
    step.runner_up_err = s.second.err;
    // Nothing left to explain (the target is in the span of what was taken).
    if (step.column < 0 || 1.0 - r.explained < kNothingLeft) break;
    step.delta_bic = bic_change(step.err, r.explained, double(fit.e.size()));
    std::vector<int> with = chosen;
    with.push_back(step.column);
    if (check) step.check_rms = rms_residual(*check, with, least_squares(fit, with));
    r.refused_by = refusal(step, chosen.size(), check_rms, check != nullptr, options);
    if (!r.refused_by.empty()) {
      r.refused = step;
      return;
    }
    chosen = with;
    check_rms = step.check_rms;
    r.steps.push_back(step);
    r.explained += step.err;
    taken[std::size_t(step.column)] = true;
    if (held) held->left -= Q.col(step.column).dot(left) / Q.col(step.column).squaredNorm() * held->Q.col(step.column);
    orthogonalise(Q, step.column, taken, held ? &*held : nullptr);
  }
}

}  // namespace

ForwardRegression forward_regression(const RegressionRows& given_fit, const ForwardRegressionOptions& options,
                                     const RegressionRows* given_check) {
  const std::vector<Eigen::Index> kept = independent_columns(given_fit.fixed);
  const RegressionRows fit = with_fixed(given_fit, kept);
  const RegressionRows check = given_check ? with_fixed(*given_check, kept) : RegressionRows{};
  ForwardRegression r;
  std::vector<int> chosen;
  choose(fit, given_check ? &check : nullptr, options, r, chosen);
  fit_chosen(fit, chosen, r);
  // Back to one coefficient per fixed column given, 0 for those left out.
  Eigen::VectorXd all = Eigen::VectorXd::Zero(given_fit.fixed.cols());
  for (std::size_t i = 0; i < kept.size(); ++i) all[kept[i]] = r.fixed_coefficients[Eigen::Index(i)];
  r.fixed_coefficients = all;
  return r;
}

}  // namespace hystbench
