#include "framework/svr/svr_report.hpp"

#include "framework/core/text.hpp"
#include "framework/io/atomic_file.hpp"
#include "framework/io/csv_format.hpp"
#include "framework/io/json_number.hpp"
#include "framework/report/cell_table.hpp"
#include "framework/report/results_readme.hpp"
#include "framework/report/provenance.hpp"
#include "framework/report/table_format.hpp"

namespace hystbench {
namespace {

using table::Format;

nlohmann::json score_json(const SignalScore& s) {
  return {{"rmse", number_or_null(s.rmse)},
          {"re", number_or_null(s.re)},
          {"max_error", number_or_null(s.max_error)},
          {"rmse_one_step", number_or_null(s.rmse_one_step)}};
}

nlohmann::json row_json(const SvrExperiment& x, const SvrTestRow& row) {
  const SvrTestSignal& s = *row.signal;
  nlohmann::json j = {{"signal", s.label},
                      {"record", x.tests[s.record].name},
                      {"samples", s.end - s.begin},
                      {"scored_samples", s.end - s.begin - row.scored_from},
                      {"svr", score_json(row.svr)}};
  j["greybox"] = row.greybox ? score_json(*row.greybox) : nlohmann::json();
  return j;
}

std::string aic_csv(const ArxSelection& a) {
  std::string out = "p,q,aic,mean_squared_error,stable,chosen\n";
  for (const ArxFit& f : a.grid)
    out += std::to_string(f.p) + "," + std::to_string(f.q) + "," + csv_number(f.aic) + "," +
           csv_number(f.mean_squared_error) + "," + (f.stable ? "1" : "0") + "," +
           (f.p == a.best.p && f.q == a.best.q ? "1" : "0") + "\n";
  return out;
}

void metric_cells(const std::optional<SignalScore>& s, Format f, std::vector<std::string>& cells) {
  cells.push_back(s ? table::format_fitness(s->rmse, f) : "–");
  cells.push_back(s ? format_number("%.2f", 100.0 * s->re) : "–");
}

table::CellTable make_table(const SvrExperiment& x, const SvrResults& r, Format f) {
  const bool md = f == Format::Markdown;
  const std::string unit = x.y_unit.empty() ? "" : " (" + table::escape(x.y_unit, f) + ")";
  const std::string re = md ? "RE (%)" : "RE (\\%)";
  table::CellTable t;
  t.label = table::label_key(x.name);
  t.header = {"Signal", "SVR ARMSE" + unit, "SVR " + re};
  if (x.greybox) t.header.insert(t.header.end(), {"Grey-box ARMSE" + unit, "Grey-box " + re});
  t.header.push_back("SVR one-step RMSE" + unit);
  for (const SvrTestRow& row : r.rows) {
    std::vector<std::string> cells{table::escape(row.signal->label, f)};
    metric_cells(row.svr, f, cells);
    if (x.greybox) metric_cells(row.greybox, f, cells);
    cells.push_back(table::format_fitness(row.svr.rmse_one_step, f));
    t.rows.push_back(std::move(cells));
  }
  const SvrHyperparameters& h = r.search.hyperparameters;
  const ArxFit& a = r.arx.best;
  std::string model = "SVR-NARX (m = " + std::to_string(x.lags.m) + ", n = " + std::to_string(x.lags.n) +
                      (x.lags.input_rate ? ", input rate" : "") + ", epsilon = " + format_number("%.3g", h.epsilon) + ", C = " + format_number("%.4g", h.C) +
                      ", sigma = " + format_number("%.4g", h.sigma) + ")";
  if (x.stage2)
    model += " then ARX(" + std::to_string(a.p) + ", " + std::to_string(a.q) + ") by AIC" +
             (x.coupling == SvrCoupling::OneStep ? " on stage 1's one-step prediction" : "");
  std::string caption = "Free-run errors of `" + x.name + "` on each test signal after a " +
                        format_number("%.0f", 100.0 * x.discard) + " % warm-up: " + model;
  if (x.greybox) caption += ", beside the grey-box `" + x.greybox->model.text() + "`";
  caption += ". ARMSE: RMS error; RE: relative RMS error.";
  t.caption = md ? caption : table::escape_latex(caption);
  return t;
}

std::string svr_method(const SvrExperiment& x) {
  std::string text =
      "One row per test signal, each simulated in free run from the measured initial samples, its first " +
      format_number("%.0f", 100.0 * x.discard) +
      " % left out as warm-up. ARMSE is the RMS of the free-run error over the rest, RE = sqrt(Σ e² / Σ y²) "
      "with the raw output (seed 002's eqs. 17–18), and the one-step RMSE predicts each sample from the "
      "measured lags. The SVR's hyperparameters were tuned by the experiment's optimizer and the ARX "
      "orders chosen by AIC (`aic.csv`); `svr.json` holds the search.";
  if (x.greybox)
    text += " The grey-box model `" + x.greybox->model.text() + "` was fitted by `hystbench fit` (" +
            x.greybox_path + ") and simulated over each whole test file.";
  return text;
}

std::string table_csv(const SvrExperiment& x, const SvrResults& r) {
  std::string out = "signal,record,svr_rmse,svr_re,svr_max_error,svr_rmse_one_step";
  if (x.greybox) out += ",greybox_rmse,greybox_re,greybox_max_error";
  out += "\n";
  for (const SvrTestRow& row : r.rows) {
    out += csv_field(row.signal->label) + "," + csv_field(x.tests[row.signal->record].name) + "," +
           csv_number(row.svr.rmse) + "," + csv_number(row.svr.re) + "," + csv_number(row.svr.max_error) + "," +
           csv_number(row.svr.rmse_one_step);
    if (row.greybox)
      out += "," + csv_number(row.greybox->rmse) + "," + csv_number(row.greybox->re) + "," +
             csv_number(row.greybox->max_error);
    out += "\n";
  }
  return out;
}

// The model, and the sampling time its lags count in (compare checks it).
nlohmann::json model_file(const SvrExperiment& x, const SvrResults& r) {
  nlohmann::json j = r.model.to_json();
  j["sample_time"] = x.stage1.data.sample_time;
  return j;
}

}  // namespace

nlohmann::json svr_json(const SvrExperiment& x, const SvrResults& r, int threads) {
  const SvrHyperparameters& h = r.search.hyperparameters;
  nlohmann::json rows = nlohmann::json::array();
  for (const SvrTestRow& row : r.rows) rows.push_back(row_json(x, row));
  nlohmann::json j = {
      {"experiment", x.source},
      {"hyperparameters", {{"epsilon", h.epsilon}, {"C", h.C}, {"sigma", h.sigma}, {"gamma", h.gamma()}}},
      {"orders",
       {{"m", x.lags.m},
        {"n", x.lags.n},
        {"p", x.stage2 ? nlohmann::json(r.arx.best.p) : nlohmann::json()},
        {"q", x.stage2 ? nlohmann::json(r.arx.best.q) : nlohmann::json()}}},
      {"search",
       {{"fixed", x.fixed.has_value()},
        {"optimizer", x.search.algorithms[0].name},
        {"params", x.search.algorithms[0].params},
        {"problem", x.search_problem->describe()},
        {"best_fitness", number_or_null(r.search.trial.best)},
        {"evaluations", r.search.trial.evaluations},
        {"trial_seed", r.search.trial.seed}}},
      {"stage1", {{"record", x.stage1.name}, {"support_vectors", r.model.regressor().support_vectors()}}},
      {"stage2", x.stage2 ? nlohmann::json{{"record", x.stage2->name}, {"aic", r.arx.best.aic}} : nlohmann::json()},
      {"rows", rows},
      {"seconds", r.seconds},
      {"provenance", provenance(threads, x.search.seed)}};
  if (x.fixed) j["search"] = {{"fixed", true}};
  if (x.greybox) j["greybox"] = {{"fit", x.greybox_path}, {"model", x.greybox->model.text()}};
  return j;
}

std::vector<std::filesystem::path> write_svr_report(const std::filesystem::path& dir, const SvrExperiment& x,
                                                    const SvrResults& r, int threads) {
  std::vector<std::pair<std::string, std::string>> files = {
      {"svr_model.json", model_file(x, r).dump(2) + "\n"},
      {"table.md", table::markdown(make_table(x, r, Format::Markdown))},
      {"table.tex", table::latex(make_table(x, r, Format::Latex))},
      {"table.csv", table_csv(x, r)},
      {"svr.json", svr_json(x, r, threads).dump(2) + "\n"},
      {"README.md", results_readme("Made by `hystbench svr` from the experiment `" + x.name +
                                       "` (in `svr.json`).", {{"table", svr_method(x)}})}};
  if (x.stage2) files.emplace_back("aic.csv", aic_csv(r.arx));
  return write_files_atomic(dir, files);
}

}  // namespace hystbench
