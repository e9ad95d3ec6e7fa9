#include "framework/discovery/proposal.hpp"

#include <algorithm>
#include <cmath>

#include "framework/core/error.hpp"
#include "framework/core/text.hpp"
#include "framework/discovery/noise_floor.hpp"
#include "framework/io/json_number.hpp"

namespace hystbench {
namespace {

// Size of the probe added at a stage, for unit-RMS terms in normalised units.
constexpr double kProbe = 1e-6;

std::string term_key(const CandidateTerm& t) { return term_stage_name(t.stage) + ": " + t.text(); }

// The product of the term's factors on every sample.
Eigen::VectorXd term_values(const CandidateTerm& t, const ModelData& data, const Model::ChainSignals& chain) {
  Eigen::VectorXd phi = Eigen::VectorXd::Ones(data.size());
  for (const TermFactor& f : t.factors) {
    const Eigen::VectorXd a = factor_signal(f, data, chain);
    for (Eigen::Index k = 0; k < a.size(); ++k) phi[k] *= f.value(a[k]);
  }
  return phi;
}

double rms_over(const Eigen::VectorXd& v, const Eigen::VectorXd& mask) {
  const double n = mask.sum();
  return n > 0 ? std::sqrt((v.array().square() * mask.array()).sum() / n) : 0.0;
}

// What the term, scaled to unit RMS on the estimation samples, changes in
// the model output (linearised); `scale` receives that RMS (0: a zero column).
Eigen::VectorXd output_change(const Model& model, const Eigen::VectorXd& x, const ModelData& data,
                              const CandidateTerm& t, const Model::ChainSignals& chain,
                              const Eigen::VectorXd& y_model, double& scale) {
  Eigen::VectorXd phi = term_values(t, data, chain);
  scale = rms_over(phi, data.estimation);
  if (!(scale > 0.0) || !std::isfinite(scale)) {
    scale = 0.0;
    return Eigen::VectorXd::Zero(phi.size());
  }
  phi *= kProbe / scale;
  Eigen::VectorXd y;
  if (!model.simulate_probed(x, data, y, t.entry(), &phi, nullptr)) {
    scale = 0.0;
    return Eigen::VectorXd::Zero(phi.size());
  }
  return (y - y_model) / kProbe;
}

// How each of the model's own parameters moves the output (forward
// differences, backward at an upper bound): the directions a refit of the
// model can already take, which a proposed term must do better than.
Eigen::MatrixXd parameter_columns(const Model& model, const Eigen::VectorXd& x, const ModelData& data,
                                  const Eigen::VectorXd& y_model) {
  const Bounds b = model.bounds();
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(data.size(), x.size());
#pragma omp parallel for schedule(dynamic)
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    const double h = x[i] + kProbe <= b.upper[i] ? kProbe : -kProbe;
    Eigen::VectorXd xi = x, y;
    xi[i] += h;
    if (model.simulate(xi, data, y)) J.col(i) = (y - y_model) / h;
  }
  return J;
}

// Rows of `m` where keep[k] is 1.
Eigen::MatrixXd rows_where(const Eigen::MatrixXd& m, const Eigen::VectorXd& keep) {
  Eigen::MatrixXd out(Eigen::Index(keep.sum()), m.cols());
  Eigen::Index r = 0;
  for (Eigen::Index k = 0; k < m.rows(); ++k)
    if (keep[k] != 0.0) out.row(r++) = m.row(k);
  return out;
}

double rms(const Eigen::VectorXd& v) { return v.size() ? std::sqrt(v.squaredNorm() / double(v.size())) : 0.0; }

}  // namespace

nlohmann::json ProposeOptions::to_json() const {
  return {{"degree", degree},
          {"max_terms", regression.max_terms},
          {"bic_threshold", regression.bic_threshold},
          {"heldout_gain", regression.heldout_gain}};
}

namespace {

// Every library term's column, the model's own sensitivities, and the
// residual, all on every sample.
struct Columns {
  Eigen::MatrixXd terms, own;
  Eigen::VectorXd scale, e;
};

Columns regression_columns(const Model& model, const Eigen::VectorXd& x, const ModelData& data,
                           const std::vector<CandidateTerm>& library) {
  Eigen::VectorXd y_model;
  Model::ChainSignals chain;
  if (!model.simulate_probed(x, data, y_model, Model::Entry::Output, nullptr, &chain))
    throw InputError("propose: the fitted model " + model.text() +
                     " diverges on these data; fit it to them first (hystbench fit)");
  const Eigen::Index m = Eigen::Index(library.size());
  Columns c{Eigen::MatrixXd(data.size(), m), parameter_columns(model, x, data, y_model), Eigen::VectorXd(m),
            data.y - y_model};
#pragma omp parallel for schedule(dynamic)
  for (Eigen::Index j = 0; j < m; ++j)
    c.terms.col(j) = output_change(model, x, data, library[std::size_t(j)], chain, y_model, c.scale[j]);
  return c;
}

// The chosen terms with their coefficients in the terms' own units.
std::vector<ProposedTerm> chosen_terms(const ForwardRegression& r, const std::vector<CandidateTerm>& library,
                                       const Eigen::VectorXd& scale, double y_scale) {
  std::vector<ProposedTerm> out;
  for (std::size_t i = 0; i < r.steps.size(); ++i) {
    const ForwardStep& s = r.steps[i];
    const double c = scale[s.column];
    out.push_back({library[std::size_t(s.column)], r.coefficients[Eigen::Index(i)] / c,
                   r.standard_errors[Eigen::Index(i)] / c, s.err, s.delta_bic, s.check_rms * y_scale,
                   s.runner_up >= 0 ? term_key(library[std::size_t(s.runner_up)]) : "", s.runner_up_err});
  }
  return out;
}

// Per stage, the term with the largest share at the first step.
std::vector<StageLead> stage_leads(const ForwardRegression& r, const std::vector<CandidateTerm>& library) {
  std::vector<StageLead> leads;
  for (std::size_t j = 0; j < library.size(); ++j) {
    const CandidateTerm& t = library[j];
    auto lead = std::find_if(leads.begin(), leads.end(), [&](const StageLead& l) { return l.stage == t.stage; });
    if (lead == leads.end()) lead = leads.insert(leads.end(), {t.stage, "", 0.0});
    if (r.first_err[Eigen::Index(j)] > lead->share) *lead = {t.stage, t.text(), r.first_err[Eigen::Index(j)]};
  }
  return leads;
}

// Residual RMS before and after the chosen terms and the refit of the
// model's own parameters that goes with them, estimation and held out.
void residual_errors(const Columns& c, const ForwardRegression& r, const ModelData& data, Proposal& p) {
  Eigen::VectorXd theta = Eigen::VectorXd::Zero(c.terms.cols());
  for (std::size_t i = 0; i < r.steps.size(); ++i) theta[r.steps[i].column] = r.coefficients[Eigen::Index(i)];
  const Eigen::VectorXd after = c.e - c.terms * theta - c.own * r.fixed_coefficients;
  const double sy = data.scales.y;
  const Eigen::VectorXd held = data.heldout_mask();
  const Eigen::VectorXd fit_e = rows_where(c.e, data.estimation), held_e = rows_where(c.e, held);
  p.n_estimation = long(fit_e.size());
  p.n_heldout = long(held_e.size());
  p.rmse_estimation = rms(fit_e) * sy;
  p.rmse_estimation_after = rms(rows_where(after, data.estimation)) * sy;
  p.rmse_heldout = rms(held_e) * sy;
  p.rmse_heldout_after = rms(rows_where(after, held)) * sy;
  p.noise_sd = estimate_noise_floor(data.u, data.y, data.segment).sigma * sy;
  const double left = p.n_heldout ? p.rmse_heldout_after : p.rmse_estimation_after;
  p.falls_short = std::isfinite(p.noise_sd) && p.noise_sd > 0.0 && left > kLibraryShort * p.noise_sd;
}

}  // namespace

Proposal propose_terms(const Model& model, const Eigen::VectorXd& x, const ModelData& data,
                       const ProposeOptions& options) {
  if (options.degree < 1 || options.degree > 6)
    throw InputError("propose: the degree must be between 1 and 6 (got " + std::to_string(options.degree) + ")");
  const std::vector<CandidateTerm> library = term_library(options.degree);
  const Columns c = regression_columns(model, x, data, library);
  const auto rows = [&](const Eigen::VectorXd& mask) {
    return RegressionRows{rows_where(c.terms, mask), rows_where(c.e, mask), rows_where(c.own, mask)};
  };
  const RegressionRows fit = rows(data.estimation), check = rows(data.heldout_mask());
  const ForwardRegression r = forward_regression(fit, options.regression, check.e.size() ? &check : nullptr);

  Proposal p;
  p.model = model.text();
  p.library_size = int(library.size());
  p.options = options;
  p.terms = chosen_terms(r, library, c.scale, data.scales.y);
  p.stage_leads = stage_leads(r, library);
  if (r.refused.column >= 0) {
    p.refused = term_key(library[std::size_t(r.refused.column)]);
    p.refused_by = r.refused_by;
    p.refused_err = r.refused.err;
    p.refused_delta_bic = r.refused.delta_bic;
  }
  residual_errors(c, r, data, p);
  return p;
}

namespace {

// What the chosen terms suggest the library lacks, in their own words: a
// play operator chosen but not enough says the loop's width is not one of
// the library's radii; a force of the speed alone (x′·|x′|, x′³) chosen but
// not enough says it may jump where the speed changes sign.
std::string library_hint(const Proposal& p) {
  bool play = false, speed_force = false;
  for (const ProposedTerm& t : p.terms) {
    const auto& f = t.term.factors;
    play = play || std::any_of(f.begin(), f.end(), [](const TermFactor& a) { return a.signal == TermSignal::Play; });
    speed_force = speed_force || (t.term.stage == TermStage::Dynamics && !f.empty() &&
                                  std::all_of(f.begin(), f.end(), [](const TermFactor& a) {
                                    return a.signal == TermSignal::Resonance && a.rate && a.odd;
                                  }));
  }
  std::string out;
  if (play)
    out += " Play operators were chosen, but the library's have three fixed radii (10, 25 and 50 % of max |v|): a "
           "loop whose width changes with the drive's rate or amplitude is none of them.";
  if (speed_force)
    out += " Odd powers of the speed x′ were chosen, but each is zero at rest: a friction force that jumps with the "
           "direction of motion (dry, Coulomb) is none of them.";
  return out;
}

}  // namespace

std::string beyond_library(const Proposal& p) {
  if (!p.falls_short) return "";
  const bool held = p.n_heldout > 0;
  const double before = held ? p.rmse_heldout : p.rmse_estimation, after = held ? p.rmse_heldout_after : p.rmse_estimation_after;
  const double excess = before * before - p.noise_sd * p.noise_sd;
  const double removed = excess > 0.0 ? (before * before - after * after) / excess : 0.0;
  return std::string("The library cannot express what is missing: with ") +
         (p.terms.empty() ? "no term" : "the terms above") + " the residual " + (held ? "on the held-out samples " : "") +
         "is still " + format_number("%.3g", after / p.noise_sd) + " times the noise floor (" +
         format_number("%.4g", after) + " against σ = " + format_number("%.4g", p.noise_sd) + "), " +
         format_number("%.0f", 100.0 * std::clamp(removed, 0.0, 1.0)) +
         " % of the error above the noise explained. Its terms are powers, play operators, square roots and "
         "products of the chain's signals at one sample; a law that changes with time (a drifting gain, "
         "heating), a state the chain does not have (a second loop, a thermal or charge state) or a jump (dry "
         "friction) is none of those." + library_hint(p) +
         " Write that effect by hand (docs/plugins.md#adding-a-physical-effect), guided by where the error "
         "concentrates (hystbench compare).";
}

nlohmann::json to_json(const std::vector<StageLead>& leads) {
  nlohmann::json out = nlohmann::json::array();
  for (const StageLead& l : leads)
    out.push_back({{"stage", term_stage_name(l.stage)},
                   {"term", l.term.empty() ? nlohmann::json(nullptr) : nlohmann::json(l.term)},
                   {"share_of_residual", number_or_null(l.share)}});
  return out;
}

namespace {

nlohmann::json factors_json(const CandidateTerm& t) {
  nlohmann::json out = nlohmann::json::array();
  for (const TermFactor& f : t.factors) {
    TermFactor signal = f;
    signal.rate = false;  // the signal's own symbol; "rate" says whether the factor is of its rate
    nlohmann::json j = {{"signal", signal.symbol()}, {"rate", f.rate}, {"odd", f.odd}};
    j["power"] = f.root ? nlohmann::json(f.exponent()) : nlohmann::json(f.power);
    if (f.signal == TermSignal::Play) j["radius"] = f.radius;
    out.push_back(j);
  }
  return out;
}

}  // namespace

nlohmann::json Proposal::to_json() const {
  nlohmann::json terms_json = nlohmann::json::array();
  for (std::size_t i = 0; i < terms.size(); ++i) {
    const ProposedTerm& t = terms[i];
    terms_json.push_back({{"rank", int(i) + 1},
                          {"stage", term_stage_name(t.term.stage)},
                          {"term", t.term.text()},
                          {"enters", entry_name(t.term.entry())},
                          {"factors", factors_json(t.term)},
                          {"coefficient", number_or_null(t.coefficient)},
                          {"standard_error", number_or_null(t.standard_error)},
                          {"share_of_residual", number_or_null(t.err)},
                          {"delta_bic", number_or_null(t.delta_bic)},
                          {"heldout_rmse_after", number_or_null(t.heldout_rmse)},
                          {"runner_up", t.runner_up.empty() ? nlohmann::json(nullptr) : nlohmann::json(t.runner_up)},
                          {"runner_up_share", number_or_null(t.runner_up_err)}});
  }
  nlohmann::json refused_json = nullptr;
  if (!refused.empty())
    refused_json = {{"term", refused}, {"refused_by", refused_by}, {"share_of_residual", number_or_null(refused_err)},
                    {"delta_bic", number_or_null(refused_delta_bic)}};
  return {{"model", model},
          {"stage_leads", hystbench::to_json(stage_leads)},
          {"library_size", library_size},
          {"options", options.to_json()},
          {"terms", terms_json},
          {"first_refused", refused_json},
          {"noise_sd", number_or_null(noise_sd)},
          {"library_falls_short", falls_short},
          {"beyond_library", falls_short ? nlohmann::json(beyond_library(*this)) : nlohmann::json(nullptr)},
          {"units", "coefficients in normalised units (u and y divided by the fit's scales, rates per second)"},
          {"residual",
           {{"estimation", {{"samples", n_estimation}, {"rmse_before", rmse_estimation}, {"rmse_after", rmse_estimation_after}}},
            {"heldout",
             {{"samples", n_heldout}, {"rmse_before", number_or_null(rmse_heldout)},
              {"rmse_after", number_or_null(rmse_heldout_after)}}}}}};
}

}  // namespace hystbench
