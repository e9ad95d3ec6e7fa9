#include "framework/discovery/diagnosis_report.hpp"

#include <omp.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "framework/discovery/candidates_figure.hpp"
#include "framework/discovery/comparison_report.hpp"
#include "framework/discovery/fit_record.hpp"
#include "framework/core/text.hpp"
#include "framework/discovery/model_comparison.hpp"
#include "framework/discovery/separability.hpp"
#include "framework/io/atomic_file.hpp"
#include "framework/report/figures.hpp"
#include "framework/report/provenance.hpp"
#include "framework/report/markdown.hpp"

namespace hystbench {
namespace {

using markdown::num;

std::string unit_suffix(const std::string& y_unit) { return y_unit.empty() ? "" : " " + y_unit; }

// A breakdown group, labelled for the list of worst groups.
struct Group {
  std::string label;
  double rmse;
};

// The group with the largest RMSE, as "label (RMSE x)"; the first of equals.
std::string worst_of(const std::vector<Group>& groups, const std::string& unit) {
  const Group* worst = nullptr;
  for (const auto& g : groups)
    if (std::isfinite(g.rmse) && (!worst || g.rmse > worst->rmse)) worst = &g;
  return worst ? worst->label + " (RMSE " + num(worst->rmse) + unit + ")" : "";
}

template <class Row, class Label>
std::vector<Group> labelled(const std::vector<Row>& rows, Label label) {
  std::vector<Group> out;
  for (const auto& r : rows) out.push_back({label(r), r.metrics.rmse});
  return out;
}

std::string worst_groups(const Comparison& where, const std::string& unit) {
  std::string out;
  const auto line = [&](const std::string& what, const std::vector<Group>& groups) {
    const std::string worst = worst_of(groups, unit);
    if (!worst.empty()) out += "- worst " + what + ": " + worst + "\n";
  };
  line("segment", labelled(where.by_segment, [](const SegmentErrors& s) { return s.segment; }));
  line("input-amplitude bin", labelled(where.by_amplitude, [](const AmplitudeErrors& b) {
         return "|u − ū| " + num(b.u_low) + "…" + num(b.u_high);
       }));
  // In the order of the branch names, as metrics.json lists them: the first
  // of equal RMSEs is named.
  const BranchErrors& b = where.by_branch;
  line("branch",
       {{"holding", b.holding.rmse}, {"loading", b.loading.rmse}, {"unloading", b.unloading.rmse}});
  line("time window", labelled(where.by_time, [](const TimeErrors& w) {
         return num(w.t_start) + "–" + num(w.t_end) + " s";
       }));
  return out.empty() ? out : out + "\n";
}

// "- `model`: name = value ± sd unit, ..." for one candidate's fit.
std::string parameter_list(const Candidate& c) {
  std::string out = "- `" + c.model.text() + "`:";
  for (const auto& p : c.check.parameters)
    out += " " + p.name + " = " + num(p.value) + (std::isfinite(p.sd) ? " ± " + num(p.sd) : "") +
           (p.unit.empty() ? "" : " " + p.unit) + ";";
  return out + "\n";
}

std::string verdict_section(const Diagnosis& d, const std::string& unit) {
  std::ostringstream out;
  out << "## Verdict\n\n";
  out << "**Complete: " << (d.completeness.complete ? "yes" : "no") << ".** "
      << d.completeness.reason << "\n\n";
  if (d.optimum.triggered)
    out << "The fit looked off its optimum (" << d.optimum.reason << "), so before any candidate: "
        << join(d.optimum.actions, "; ") << ".\n\n";
  const Candidate* w = d.winner();
  if (!w) {
    if (!d.beyond.refused.empty())
      out << "**none**: " << d.beyond.refused << " is significant but removes only "
          << num(100.0 * d.beyond.refused_share) << " % of the error left above the noise on the "
          << d.beyond.judged_on << " data; an effect must remove " << num(100.0 * kPartialShare)
          << " % to be added.";
    else
      out << "**none**: no effect of the catalog improves the fit enough (ΔBIC ≤ "
          << num(d.options.value("bic_threshold", -10.0)) << " and a held-out RMSE at least "
          << num(100.0 * d.options.value("heldout_gain", 0.01)) << " % lower).";
    // The same judgement as the completeness line above, in terms of what to do.
    if (d.completeness.complete)
      out << " The model has nothing systematic left to find.";
    else if (d.completeness.kind == "coloured_at_floor")
      out << " The error is at the noise estimate but the residual is not white, which points "
             "at coloured measurement noise rather than at a missing effect.";
    else if (d.completeness.kind == "noise_estimate_too_high")
      out << " The noise estimate is wrong on this record (the error is below it), so nothing "
             "is judged against it.";
    else if (d.completeness.kind == "beyond_catalog")
      out << " See \"Beyond the catalog\" below.";
    else if (d.completeness.kind == "systematic")
      out << " Something systematic is left that no catalog effect captures, or the fit is "
             "stuck; consider writing an effect of your own (docs/plugins.md, \"Adding a "
             "physical effect\").";
    out << "\n\n";
    return out.str();
  }
  out << "**" << w->effect << "** is missing. Adding it lowers the RMSE from "
      << num(d.errors.rmse_estimation) << " to " << num(w->after.rmse_estimation) << unit;
  if (d.errors.n_heldout)
    out << " on the estimation data and from " << num(d.errors.rmse_heldout) << " to "
        << num(w->after.rmse_heldout) << unit << " on the held-out data";
  out << " (ΔBIC = " << num(w->delta_bic) << ").\n\n" << w->evidence << "\n\n";
  if (d.close_call.close) {
    out << "**Close call**: " << d.close_call.reason << ". Both fits:\n\n";
    for (const Candidate* c : {w, d.find(d.close_call.runner_up)})
      if (c) out << parameter_list(*c);
    out << "\n";
  }
  out << "Next: `--model " << w->model.text() << "` (its fit is in `extended_fit.json`).\n\n";
  return out.str();
}

std::string where_section(const Diagnosis& d, const std::string& unit,
                          const std::string& current_report) {
  std::ostringstream out;
  out << "## Where the current model fails\n\n";
  out << "Model `" << d.model.text() << "`: RMSE " << num(d.errors.rmse_estimation) << unit
      << " (estimation)";
  if (d.errors.n_heldout) out << ", " << num(d.errors.rmse_heldout) << unit << " (held out)";
  out << "; estimated noise σ " << num(d.where.noise_floor.sigma) << unit;
  out << ".\n\n";
  out << worst_groups(d.where, unit);
  out << "\n" << d.where.excitation.summary() << "\n";
  if (d.where.startup.worth_saying()) out << "- " << d.where.startup.sentence() << "\n";
  for (const auto& p : inseparable_pairs(d.model.effects(), d.where.excitation))
    out << "- " << p.sentence(d.where.excitation) << "\n";
  out << "\n";
  for (const auto& warning : d.check.warnings()) out << "- " << warning << "\n";
  if (!d.check.warnings().empty()) out << "\n";
  out << "Full breakdowns, residual tests and figures: [" << current_report << "](" << current_report
      << ").\n\n";
  return out.str();
}

std::string candidates_section(const Diagnosis& d, const std::string& unit) {
  std::ostringstream out;
  out << "## Candidates, best first\n\n";
  out << markdown::header_row({"effect", "Δk", "ΔBIC", "RMSE after" + unit,
                               "held-out RMSE after" + unit, "significant"});
  for (const auto& c : d.candidates)
    out << markdown::row({c.effect, std::to_string(c.delta_k), num(c.delta_bic),
                          num(c.after.rmse_estimation),
                          d.errors.n_heldout ? num(c.after.rmse_heldout) : "–",
                          c.significant ? "yes" : "no"});
  out << "\nEach candidate is the current model with one more effect, refitted from the current "
         "fit (the new effect starts neutral, so it can only improve the estimation error). ΔBIC = "
         "N ln(SSE_new/SSE_old) + Δk ln N over the N estimation samples.\n\n";
  for (const auto& c : d.candidates) out << "- **" << c.effect << "**: " << c.evidence << "\n";
  out << "\nFitted parameters of every candidate (± standard error):\n\n";
  for (const auto& c : d.candidates) out << parameter_list(c);
  out << "\n![candidates](diagnosis_candidates.png)\n";
  return out.str();
}

}  // namespace

std::string diagnosis_markdown(const Diagnosis& d, const std::string& data_name,
                               const std::string& y_unit, const std::string& current_report) {
  const std::string unit = unit_suffix(y_unit);
  return "# Diagnosis of `" + d.model.text() + "` on " + data_name + "\n\n" +
         verdict_section(d, unit) + where_section(d, unit, current_report) +
         beyond_catalog_markdown(d.beyond, data_name) + candidates_section(d, unit);
}

std::vector<std::filesystem::path> write_diagnosis(const std::filesystem::path& dir,
                                                   const Diagnosis& d, const ModelData& data,
                                                   const DataSource& source,
                                                   const HoldoutSpec& holdout, std::string& note) {
  namespace fs = std::filesystem;
  fs::create_directories(dir);
  const std::uint64_t seed =
      d.options.value("fit", nlohmann::json::object()).value("seed", std::uint64_t{1});
  nlohmann::json j = d.to_json();
  j["data"] = source.to_json();
  j["holdout"] = holdout.text();
  j["holdout_description"] = describe_holdout(data, holdout);
  std::vector<fs::path> files{dir / "diagnosis.json", dir / "fit.json", dir / "report.md"};
  write_file_atomic(dir / "fit.json",
                    make_fit_record(d.model, d.x, data, source, holdout, seed).to_json().dump(2) + "\n");
  if (const Candidate* w = d.winner()) {
    files.push_back(dir / "extended_fit.json");
    write_file_atomic(files.back(), make_fit_record(w->model, w->x, data, source, holdout, seed)
                                            .to_json().dump(2) + "\n");
  }
  Eigen::VectorXd y;
  if (!simulate_physical(d.model, d.x, data, y)) y = Eigen::VectorXd::Zero(data.size());
  const auto current = write_comparison(dir / "current",
                                        comparison_input(data, std::move(y), source.u_unit, source.y_unit),
                                        d.where, "Current model " + d.model.text(), d.model.text());
  files.insert(files.end(), current.begin(), current.end());
  const auto script = write_candidates_figure(dir, d, source.y_unit);
  files.push_back(script);
  for (const auto& image : render_figures(dir, {script}, note)) files.push_back(image);
  j["provenance"] = provenance(omp_get_max_threads(), seed);
  write_file_atomic(dir / "diagnosis.json", j.dump(2) + "\n");
  write_file_atomic(dir / "report.md",
                    diagnosis_markdown(d, source.file_name(), source.y_unit, "current/report.md") +
                        "\n## Hold-out\n\n" + describe_holdout(data, holdout) + "\n");
  return files;
}

}  // namespace hystbench
