#include "framework/discovery/ladder_report.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <sstream>

#include "framework/discovery/diagnosis_report.hpp"
#include "framework/discovery/fit_record.hpp"
#include "framework/discovery/ladder_checkpoint.hpp"
#include "framework/discovery/separability.hpp"
#include "framework/discovery/sound_rung.hpp"
#include "framework/io/atomic_file.hpp"
#include "framework/report/figures.hpp"
#include "framework/report/gnuplot_script.hpp"
#include "framework/report/markdown.hpp"
#include "framework/report/provenance.hpp"
#include "framework/core/text.hpp"

namespace hystbench {
namespace {

// What the record excites, and which effects of the final model it cannot
// tell apart (separability.hpp).
std::string excitation_section(const Ladder& ladder) {
  const ExcitationContent& e = ladder.diagnoses.back().where.excitation;
  std::string out = "## What the record can tell apart\n\n" + e.summary() + "\n";
  const StartupTransient& t = ladder.diagnoses.back().where.startup;
  if (t.dominates) out += "\n**" + t.sentence() + "**\n";
  const auto pairs = inseparable_pairs(ladder.final_effects(), e);
  for (const auto& p : pairs) out += "\n- " + p.sentence(e);
  if (pairs.empty()) out += "\nIt separates every pair of effects in the final model that can take over each other's role.";
  return out + "\n";
}

nlohmann::json inseparable_json(const Ladder& ladder) {
  const ExcitationContent& e = ladder.diagnoses.back().where.excitation;
  nlohmann::json out = nlohmann::json::array();
  for (const auto& p : inseparable_pairs(ladder.final_effects(), e))
    out.push_back({{"effect", p.effect}, {"rival", p.rival}, {"needs", need_text(p.need)}, {"sentence", p.sentence(e)}});
  return out;
}


using markdown::num;

double estimated_sigma(const Ladder& ladder) {
  return ladder.diagnoses.back().where.noise_floor.sigma;
}

nlohmann::json close_call_json(const CloseCall& c) {
  return {{"close", c.close}, {"reason", c.reason}, {"runner_up", c.runner_up}};
}

std::string step_label(const LadderStep& s) {
  std::string label = s.added.empty() ? "start" : "+" + s.added;
  if (!s.added.empty() && !s.model.has(s.added)) label += " (dropped)";
  for (const auto& r : s.removed) label += " −" + r;
  return label;
}

std::filesystem::path write_ladder_figure(const std::filesystem::path& dir, const Ladder& ladder,
                                          const LadderContext& ctx) {
  std::ostringstream csv;
  csv << "step,label,rmse,heldout_rmse\n";
  for (std::size_t k = 0; k < ladder.steps.size(); ++k) {
    const auto& s = ladder.steps[k];
    csv << k << "," << step_label(s) << "," << gnuplot::number(s.errors.rmse_estimation) << ","
        << gnuplot::number(s.errors.n_heldout ? s.errors.rmse_heldout : std::nan("")) << "\n";
  }
  write_file_atomic(dir / "ladder.csv", csv.str());
  const std::string unit = ctx.source.y_unit.empty() ? "" : " [" + ctx.source.y_unit + "]";
  std::ostringstream body;
  body << "set datafile separator ','\n" << gnuplot::key_above_plot() << "set grid\n"
       << "set logscale y\nset xtics noenhanced\nset offsets 0.3, 0.3, 0, 0\n"
       << "set xlabel 'effect added at each step'\n"
       << "set ylabel " << gnuplot::quoted("RMSE" + unit) << "\n"
       << "set title " << gnuplot::quoted("Discovery from " + ladder.steps.front().model.text())
       << " noenhanced\n"
       << "sigma = " << gnuplot::number(estimated_sigma(ladder)) << "\n"
       << "truth = " << gnuplot::number(ctx.true_noise_sd.value_or(std::nan(""))) << "\n"
       << "plot 'ladder.csv' using 1:3:xtic(2) with linespoints lw 2 pt 7 title 'estimation', \\\n"
       << "     '' using 1:4 with linespoints lw 2 pt 5 title 'held out', \\\n"
       << "     sigma with lines dt 2 lw 2 lc rgb '#808080' title 'σ estimated'"
       << (ctx.true_noise_sd ? ", \\\n     truth with lines dt 3 lw 2 lc rgb 'black' title 'σ true'"
                             : "")
       << "\n";
  const std::string text =
      gnuplot::header("ladder", "the error falling as effects are added (σ: the noise sd)", "ladder.csv") +
      gnuplot::render_all_terminals("ladder", body.str());
  return gnuplot::write_script(dir, "ladder", text);
}

}  // namespace

nlohmann::json ladder_json(const Ladder& ladder, const LadderContext& ctx) {
  nlohmann::json steps = nlohmann::json::array();
  for (std::size_t k = 0; k < ladder.steps.size(); ++k) {
    const auto& s = ladder.steps[k];
    const FitRecord r{s.model, s.x, ctx.data.scales, ctx.source, ctx.holdout};
    nlohmann::json parameters = nlohmann::json::object(), units = nlohmann::json::object();
    for (const auto& p : r.parameters_json()) {
      parameters[p["name"].get<std::string>()] = p["value"];
      units[p["name"].get<std::string>()] = p["unit"];
    }
    const auto e = s.errors.to_json();
    steps.push_back({{"step", k},
                     {"added", s.added},
                     {"removed", s.removed},
                     {"effects", s.model.effects()},
                     {"model", s.model.text()},
                     {"parameters", parameters},
                     {"units", units},
                     {"rmse", e["rmse"]},
                     {"heldout_rmse", e["heldout_rmse"]},
                     {"bic", s.bic},
                     {"evidence", s.evidence},
                     {"attribution", s.attribution},
                     {"nesting_refits", to_json(s.nesting)},
                     {"sub_models", to_json(s.sub_models)},
                     {"verdict", ladder.diagnoses[k].verdict},
                     {"close_call", close_call_json(ladder.diagnoses[k].close_call)},
                     {"optimum", ladder.diagnoses[k].optimum.to_json()},
                     {"complete", ladder.diagnoses[k].completeness.complete},
                     {"check", ladder.diagnoses[k].check.to_json()}});
  }
  const Completeness& c = ladder.completeness();
  nlohmann::json j = {{"complete", c.complete},
                      {"reason", c.reason},
                      {"completeness", c.to_json()},
                      {"finished", ladder.finished()},
                      {"steps", steps},
                      {"final_effects", ladder.final_effects()},
                      {"excitation", ladder.diagnoses.back().where.excitation.to_json()},
                      {"inseparable", inseparable_json(ladder)},
                      {"startup_transient", ladder.diagnoses.back().where.startup.to_json()},
                      {"final_model", ladder.steps.back().model.text()},
                      {"propose_from", sound_rung(ladder).to_json()},
                      {"stopped_by_limit", ladder.stopped_by_limit},
                      {"noise_floor", {{"estimated_sigma", estimated_sigma(ladder)}}},
                      {"data", ctx.source.to_json()},
                      {"holdout", ctx.holdout.text()},
                      {"holdout_description", describe_holdout(ctx.data, ctx.holdout)},
                      {"options", ctx.options}};
  if (ctx.true_noise_sd) j["noise_floor"]["true_sigma"] = *ctx.true_noise_sd;
  if (!std::isfinite(estimated_sigma(ladder))) j["noise_floor"]["estimated_sigma"] = nullptr;
  return j;
}

namespace {

std::string completeness_section(const Ladder& ladder) {
  const Completeness& c = ladder.completeness();
  std::string out = std::string("**Complete: ") + (c.complete ? "yes" : "no") + ".** " + c.reason;
  if (!c.complete && c.kind != "beyond_catalog" && ladder.finished() && !ladder.stopped_by_limit)
    out += " No catalog effect improves the fit significantly: what is missing is either not in "
           "the catalog (docs/plugins.md, \"Adding a physical effect\") or hidden by the noise.";
  return out + "\n\n";
}

std::string status_sentence(const Ladder& ladder) {
  const std::string from = "Started from `" + ladder.steps.front().model.text() + "`";
  const std::string model = std::string("`").append(ladder.steps.back().model.text()).append("`");
  if (!ladder.finished()) return from + "; the ladder is still running, now at " + model + ".";
  return from + ", ended with " + model +
         (ladder.stopped_by_limit ? " (stopped at the step limit, the last verdict still named an effect)"
                                  : " (the last diagnosis found nothing significant to add)") +
         ".";
}

std::string parameters_section(const ModelCheck& check) {
  std::ostringstream out;
  out << "## Final parameters\n\n"
      << markdown::header_row({"parameter", "value", "standard error", "unit", "note"});
  for (const auto& p : check.parameters) {
    std::string note = p.at_bound ? "on a bound" : "";
    if (std::isfinite(p.seconds))
      note += (note.empty() ? "" : "; ") + num(p.seconds) + " ± " + num(p.sd_seconds) + " s";
    out << markdown::row({"`" + p.name + "`", num(p.value),
                          std::isinf(p.sd) ? "undetermined" : num(p.sd), p.unit, note});
  }
  out << "\nStandard errors from the Jacobian at the optimum, s²(JᵀJ)⁻¹; they assume a white "
         "residual and are too small when it is not.\n\n";
  for (const auto& w : check.warnings()) out << "- " << w << "\n";
  return out.str();
}

}  // namespace

std::string ladder_markdown(const Ladder& ladder, const LadderContext& ctx) {
  const std::string unit = ctx.source.y_unit.empty() ? "" : " " + ctx.source.y_unit;
  std::ostringstream out;
  out << "# Discovery on " << ctx.source.file_name() << "\n\n" << completeness_section(ladder);
  out << status_sentence(ladder) << "\n\n";
  out << markdown::header_row({"step", "added", "model", "k", "RMSE" + unit,
                               "held-out RMSE" + unit, "BIC", "complete"});
  for (std::size_t k = 0; k < ladder.steps.size(); ++k) {
    const auto& s = ladder.steps[k];
    out << markdown::row({std::to_string(k), step_label(s), s.model.text(),
                          std::to_string(s.model.dimension()), num(s.errors.rmse_estimation),
                          s.errors.n_heldout ? num(s.errors.rmse_heldout) : "–", num(s.bic),
                          ladder.diagnoses[k].completeness.complete ? "yes" : "no"});
  }
  out << "\nEstimated noise σ " << num(estimated_sigma(ladder)) << unit;
  if (ctx.true_noise_sd) out << "; true noise σ " << num(*ctx.true_noise_sd) << unit;
  out << ". Held out: " << describe_holdout(ctx.data, ctx.holdout) << "\n\n";
  out << "![ladder](ladder.png)\n\n## Why each effect was added\n\n";
  if (ladder.steps.size() == 1) out << "None was added.\n";
  for (std::size_t k = 1; k < ladder.steps.size(); ++k) {
    const Diagnosis& d = ladder.diagnoses[k - 1];
    out << k << ". **" << ladder.steps[k].added << "**: " << ladder.steps[k].evidence
        << " ([diagnosis](step_" << k - 1 << "/report.md))";
    if (d.close_call.close) out << " *Close call*: " << d.close_call.reason << ".";
    if (!ladder.steps[k].attribution.empty()) out << " " << ladder.steps[k].attribution;
    for (const auto& n : ladder.steps[k].nesting) out << " " << n.sentence();
    out << "\n";
  }
  for (std::size_t k = 0; k < ladder.diagnoses.size(); ++k)
    if (ladder.diagnoses[k].optimum.triggered)
      out << "\nStep " << k << ": the fit looked off its optimum (" << ladder.diagnoses[k].optimum.reason
          << "); " << join(ladder.diagnoses[k].optimum.actions, "; ") << ".\n";
  const std::string beyond = beyond_catalog_markdown(ladder.diagnoses.back().beyond, ctx.source.file_name(), "DIR");
  if (!beyond.empty()) out << "\n" << beyond << "Given this folder, " << sound_rung(ladder).sentence() << "\n\n";
  out << "\n" << excitation_section(ladder);
  out << "\n" << parameters_section(ladder.diagnoses.back().check);
  out << "\nThe last diagnosis: [step_" << ladder.steps.size() - 1 << "/report.md](step_"
      << ladder.steps.size() - 1 << "/report.md). Final fit: `fit.json` (use it with "
      << "`hystbench compare`).\n";
  return out.str();
}

std::vector<std::filesystem::path> write_ladder(const std::filesystem::path& dir,
                                                const Ladder& ladder, const LadderContext& ctx,
                                                std::string& note, std::size_t first_step) {
  std::vector<std::filesystem::path> files;
  for (std::size_t k = std::max(first_step, ladder.restored); k < ladder.diagnoses.size(); ++k) {
    const auto step = write_diagnosis(dir / ("step_" + std::to_string(k)), ladder.diagnoses[k],
                                      ctx.data, ctx.source, ctx.holdout, note);
    files.insert(files.end(), step.begin(), step.end());
  }
  const auto& last = ladder.steps.back();
  const std::uint64_t seed =
      ctx.options.value("fit", nlohmann::json::object()).value("seed", std::uint64_t{1});
  FitRecord final_fit = make_fit_record(last.model, last.x, ctx.data, ctx.source, ctx.holdout, seed);
  write_file_atomic(dir / "fit.json", final_fit.to_json().dump(2) + "\n");
  write_file_atomic(dir / "checkpoint.json",
                    checkpoint_json(ladder, checkpoint_context(ctx)).dump(1) + "\n");
  auto j = ladder_json(ladder, ctx);
  j["provenance"] = provenance(omp_get_max_threads(), seed);
  write_file_atomic(dir / "ladder.json", j.dump(2) + "\n");
  write_file_atomic(dir / "ladder.md", ladder_markdown(ladder, ctx));
  const auto script = write_ladder_figure(dir, ladder, ctx);
  files.insert(files.end(), {dir / "fit.json", dir / "checkpoint.json", dir / "ladder.json",
                             dir / "ladder.md", script});
  for (const auto& image : render_figures(dir, {script}, note)) files.push_back(image);
  return files;
}

namespace {

// FNV-1a over the bytes of the signals and the hold-out mask: a file
// regenerated under the same name is other data.
std::string data_fingerprint(const ModelData& d) {
  std::uint64_t h = 14695981039346656037ull;
  const auto mix = [&h](const Eigen::VectorXd& v) {
    const auto* bytes = reinterpret_cast<const unsigned char*>(v.data());
    for (std::size_t i = 0; i < std::size_t(v.size()) * sizeof(double); ++i)
      h = (h ^ bytes[i]) * 1099511628211ull;
  };
  for (const auto* v : {&d.t, &d.u, &d.y, &d.estimation}) mix(*v);
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
  return text;
}

}  // namespace

nlohmann::json checkpoint_context(const LadderContext& ctx) {
  return {{"data", ctx.source.to_json()},
          {"samples", ctx.data.size()},
          {"data_fingerprint", data_fingerprint(ctx.data)},
          {"holdout", ctx.holdout.text()},
          {"options", ctx.options}};
}

std::filesystem::path write_first_step(const std::filesystem::path& dir, const Diagnosis& d,
                                       const LadderContext& ctx) {
  Ladder ladder;
  ladder.steps.push_back(rung_of(d));
  ladder.diagnoses.push_back(d);
  const auto path = dir / "checkpoint.json";
  write_file_atomic(path, checkpoint_json(ladder, first_step_context(ctx)).dump(1) + "\n");
  return path;
}

nlohmann::json first_step_options(const Model& start, const DiagnoseOptions& o, int substeps) {
  nlohmann::json j = {
      {"start", start.text()}, {"fit", o.fit.to_json()}, {"diagnose", o.to_json()}, {"substeps", substeps}};
  // Written only when not the default, so that earlier checkpoints still match.
  if (start.input_hold() != InputHold::Spline) j["input_hold"] = to_string(start.input_hold());
  return j;
}

nlohmann::json first_step_context(const LadderContext& ctx) {
  nlohmann::json j = checkpoint_context(ctx);
  for (const char* key : {"max_steps", "refit_restarts"}) j["options"].erase(key);
  return j;
}

}  // namespace hystbench
