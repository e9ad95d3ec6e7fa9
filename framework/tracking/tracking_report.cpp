#include "framework/tracking/tracking_report.hpp"

#include <cmath>

#include "framework/core/text.hpp"
#include "framework/io/atomic_file.hpp"
#include "framework/io/csv_format.hpp"
#include "framework/io/json_number.hpp"
#include "framework/report/cell_table.hpp"
#include "framework/report/results_readme.hpp"
#include "framework/report/provenance.hpp"
#include "framework/report/table_format.hpp"
#include "framework/robust/linear_system.hpp"

namespace hystbench {
namespace {

using table::Format;

nlohmann::json matrix_json(const Eigen::MatrixXd& m) {
  nlohmann::json rows = nlohmann::json::array();
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (Eigen::Index j = 0; j < m.cols(); ++j) row.push_back(m(i, j));
    rows.push_back(row);
  }
  return rows;
}

nlohmann::json system_json(const robust::StateSpace& s) {
  return {{"A", matrix_json(s.A)}, {"B", matrix_json(s.B)}, {"C", matrix_json(s.C)}, {"D", matrix_json(s.D)}};
}

nlohmann::json roots_json(const Eigen::VectorXcd& roots) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& r : roots) out.push_back({r.real(), r.imag()});
  return out;
}

nlohmann::json controller_part(const robust::StateSpace& k, const robust::StateSpace& kd, const ControllerCheck& c) {
  return {{"order", k.states()},
          {"poles", roots_json(robust::poles(k))},
          {"zeros", roots_json(robust::zeros(k))},
          {"discrete_poles", roots_json(robust::poles(kd))},
          {"norm", number_or_null(c.norm)},
          {"stable", c.stable},
          {"stable_at_uncertainty_edges", c.edges_stable},
          {"discrete_loop_spectral_radius", c.spectral_radius},
          {"continuous", system_json(k)},
          {"discrete", system_json(kd)}};
}

nlohmann::json seed_json(const SeedNumbersCheck& c) {
  return {{"L_poles", roots_json(c.l_poles)},
          {"L_zeros", roots_json(c.l_zeros)},
          {"L_dc_gain", c.l_dc_gain},
          {"K3_loop_max_real_pole", c.k3_max_real},
          {"K3_loop_max_real_pole_other_sign", c.k3_max_real_other_sign},
          {"K3_discrete_loop_spectral_radius", c.k3_spectral_radius},
          {"eq25_with_printed_L", c.eq25_printed},
          {"eq25_stable_L_gamma_min", c.eq25_gamma_min},
          {"eq25_stable_L_norm_with_K_zero", c.eq25_norm_without_controller}};
}

nlohmann::json uncertainty_json(const UncertaintyWeight& w) {
  nlohmann::json points = nlohmann::json::array();
  for (const auto& p : w.points)
    points.push_back({{"record", p.record}, {"segment", p.segment}, {"hz", p.hz}, {"bound", p.bound}});
  return {{"source", w.source}, {"num", w.num}, {"den", w.den}, {"margin", w.margin}, {"rise", w.rise},
          {"points", points}};
}

std::string percent(double v) { return std::isfinite(v) ? format_number("%.2f", 100.0 * v) : "–"; }

table::CellTable make_table(const TrackingExperiment& x, const TrackingResults& r, Format f) {
  const bool md = f == Format::Markdown;
  const std::string unit = " (" + table::escape(x.y_unit, f) + ")";
  table::CellTable t;
  t.label = table::label_key(x.name);
  t.header = {"Amplitude" + unit, "Frequency (Hz)"};
  for (const auto& c : x.controllers)
    t.header.insert(t.header.end(), {table::escape(c.label, f) + " ARMSE" + unit,
                                     table::escape(c.label, f) + (md ? " RE (%)" : " RE (\\%)")});
  bool marked = false;
  for (std::size_t i = 0; i < r.rows.size(); i += x.controllers.size()) {
    const TrackingReference& ref = *r.rows[i].reference;
    std::vector<std::string> cells{format_number("%g", ref.amplitude), ref.frequencies};
    for (std::size_t c = 0; c < x.controllers.size(); ++c) {
      const TrackingRow& row = r.rows[i + c];
      const std::string mark = row.status.empty() ? "" : (md ? " †" : "$^\\dagger$");
      marked = marked || !row.status.empty();
      cells.push_back((std::isfinite(row.run.score.armse) ? format_number("%.4f", row.run.score.armse) : "–") + mark);
      cells.push_back(percent(row.run.score.re));
    }
    t.rows.push_back(std::move(cells));
  }
  std::string caption = "Tracking errors of `" + x.name + "` at " + format_number("%g", 1.0 / x.sample_time) +
                        " Hz over whole periods after settling. ARMSE: mean per-period RMS error; RE: "
                        "sum|e| / sum|y - offset|.";
  if (marked) caption += " †: limited; see tracking.json.";
  t.caption = md ? caption : table::escape_latex(caption);
  return t;
}

std::string tracking_method(const TrackingExperiment& x) {
  return "One row per reference signal, one pair of columns per controller. The loop runs at " +
         format_number("%g", 1.0 / x.sample_time) + " Hz; errors are taken over whole periods after " +
         "the settling time. ARMSE is the mean over periods of each period's RMS error, RE = Σ|e| / "
         "Σ|y − offset| (seed 002's Table 2). Plant: " + x.plant_description + ". The controllers "
         "were built from " + x.identified.description + " (`controller.json`). A cell marked † did "
         "not track as asked: its row's status in `tracking.json` says whether the reference was out of "
         "the actuator's range or the amplifier limited.";
}

std::string table_csv(const TrackingResults& r) {
  std::string out = "signal,controller,amplitude,armse,re,rmse,max_error,inverse_rms_residual,saturated_scored_samples,status\n";
  for (const TrackingRow& row : r.rows) {
    const TrackingScore& s = row.run.score;
    out += csv_field(row.reference->label) + "," + csv_field(row.controller->label) + "," +
           csv_number(row.reference->amplitude) + "," + csv_number(s.armse) + "," + csv_number(s.re) + "," +
           csv_number(s.rmse) + "," + csv_number(s.max_error) + "," + csv_number(row.run.inverse.rms_residual()) +
           "," + std::to_string(row.run.saturated_in_window) + "," + csv_field(row.status) + "\n";
  }
  return out;
}

}  // namespace

nlohmann::json controller_json(const TrackingExperiment& x, const TrackingResults& r) {
  const ControllerDesign& d = r.design;
  const PerformanceWeight& p = x.design.performance;
  nlohmann::json reduced = controller_part(d.reduced, d.reduced_discrete, d.reduced_check);
  reduced["method"] = d.reduction;
  reduced["hankel_singular_values"] = d.hankel;
  reduced["error_bound"] = d.reduction_bound;
  reduced["error_hinf"] = d.reduction_error;
  reduced["relative_error_1hz_1khz"] = d.reduction_relative_error;
  return {
      {"sample_time", x.sample_time},
      {"nominal",
       {{"num", r.nominal.num},
        {"den", r.nominal.den},
        {"p", r.nominal.p},
        {"q", r.nominal.q},
        {"misfit", r.nominal.misfit},
        {"poles", roots_json(robust::poles(r.nominal.discrete))},
        {"zeros", roots_json(robust::zeros(r.nominal.discrete))},
        {"feedforward", system_json(r.nominal.feedforward)}}},
      {"uncertainty", uncertainty_json(r.uncertainty)},
      {"performance", {{"bandwidth_hz", p.bandwidth_hz}, {"peak", p.peak}, {"low_frequency_error", p.low_frequency_error}}},
      {"generalized_plant",
       {{"inputs", {"w (reference)", "u (control)"}},
        {"outputs", {"Wp e", "Wa u", "e (measurement)"}},
        {"system", system_json(d.plant)}}},
      {"gamma_min", d.gamma_min},
      {"gamma", d.gamma},
      {"full", controller_part(d.full, d.full_discrete, d.full_check)},
      {"reduced", reduced},
      {"reachable_output", {r.reachable_low, r.reachable_high}},
      {"seed_printed_design", seed_json(r.seed_check)},
      {"design_seconds", r.design_seconds}};
}

nlohmann::json tracking_json(const TrackingExperiment& x, const TrackingResults& r, int threads) {
  nlohmann::json rows = nlohmann::json::array();
  for (const TrackingRow& row : r.rows) {
    const TrackingScore& s = row.run.score;
    const InverseStatistics& inv = row.run.inverse;
    rows.push_back({{"signal", row.reference->label},
                    {"controller", row.controller->label},
                    {"amplitude", row.reference->amplitude},
                    {"armse", number_or_null(s.armse)},
                    {"re", number_or_null(s.re)},
                    {"rmse", number_or_null(s.rmse)},
                    {"max_error", number_or_null(s.max_error)},
                    {"status", row.status},
                    {"inverse",
                     {{"max_residual", inv.max_residual},
                      {"rms_residual", inv.rms_residual()},
                      {"saturated_samples", inv.saturated},
                      {"saturated_scored_samples", row.run.saturated_in_window},
                      {"samples", inv.samples},
                      {"max_evaluations", inv.max_evaluations}}}});
  }
  return {{"experiment", x.source}, {"rows", rows}, {"seconds", r.seconds},
          {"provenance", provenance(threads, x.seed)}};
}

std::vector<std::filesystem::path> write_tracking_report(const std::filesystem::path& dir,
                                                         const TrackingExperiment& x, const TrackingResults& r,
                                                         int threads) {
  const std::vector<std::pair<std::string, std::string>> files = {
      {"controller.json", controller_json(x, r).dump(2) + "\n"},
      {"tracking.json", tracking_json(x, r, threads).dump(2) + "\n"},
      {"table.md", table::markdown(make_table(x, r, Format::Markdown))},
      {"table.tex", table::latex(make_table(x, r, Format::Latex))},
      {"table.csv", table_csv(r)},
      {"README.md", results_readme("Made by `hystbench track` from the experiment `" + x.name +
                                       "` (in `tracking.json`).", {{"table", tracking_method(x)}})}};
  return write_files_atomic(dir, files);
}

}  // namespace hystbench
