#include "framework/report/results_folder.hpp"

#include "framework/report/results_readme.hpp"

#include <algorithm>
#include <sstream>

#include "framework/io/atomic_file.hpp"
#include "framework/report/convergence.hpp"
#include "framework/report/figures.hpp"
#include "framework/report/provenance.hpp"
#include "framework/report/results_readme.hpp"
#include "framework/report/runtime_figures.hpp"
#include "framework/report/stats_tables.hpp"
#include "framework/report/tables.hpp"
#include "framework/report/trial_statistics.hpp"

namespace hystbench {
namespace {

std::optional<double> noise_floor_of(const Problem& problem) {
  const auto d = problem.describe();
  if (d.contains("noise_floor_sse")) return d["noise_floor_sse"].get<double>();
  return std::nullopt;
}

// The trials present, not the experiment's count: a results folder may hold
// one slice of the trials (run --trial-range).
long trials_per_algorithm(const std::vector<std::vector<TrialResult>>& results) {
  std::size_t most = 0;
  for (const auto& r : results) most = std::max(most, r.size());
  return static_cast<long>(most);
}

ReportContext report_context(const Experiment& e, const Problem& problem,
                             const std::vector<std::vector<TrialResult>>& results) {
  ReportContext ctx{e.name,  problem.name(),          describe_budget(e.budget),
                    trials_per_algorithm(results), e.seed, noise_floor_of(problem), "", "",
                    problem.describe().value("fitness", ""), e.table_layout == "seed"};
  if (const auto* model = dynamic_cast<const SignalModelProblem*>(&problem)) {
    ctx.input_unit = model->input_unit();
    ctx.output_unit = model->output_unit();
  }
  return ctx;
}

std::vector<AlgorithmSummary> summarize_all(const Experiment& e, const Problem& problem,
                                            const std::vector<std::vector<TrialResult>>& results) {
  std::vector<AlgorithmSummary> out;
  for (std::size_t a = 0; a < results.size(); ++a) {
    const auto& spec = e.algorithms[a];
    out.push_back(summarize(spec.label, spec.name, spec.params, problem.bounds().names, results[a]));
  }
  return out;
}

nlohmann::json summary_json(const std::filesystem::path& dir, const Experiment& e,
                            const Problem& problem,
                            const std::vector<AlgorithmSummary>& summaries, int threads) {
  nlohmann::json algs = nlohmann::json::array();
  for (const auto& s : summaries) algs.push_back(s.to_json());
  // experiment_dir: where relative paths of the problem resolve, so that
  // `hystbench report` can rebuild the problem. Relative to the results
  // folder: a folder committed with its repository keeps working after a
  // clone, and no path of the machine that ran it is written.
  std::error_code ec;
  const auto base = std::filesystem::absolute(e.base_dir, ec).lexically_normal();
  const auto here = std::filesystem::absolute(dir, ec).lexically_normal();
  const auto experiment_dir = base.lexically_relative(here);
  return {{"experiment", e.to_json()},
          {"experiment_dir", (experiment_dir.empty() ? base : experiment_dir).string()},
          {"problem", problem.describe()},
          {"algorithms", algs},
          {"provenance", provenance(threads, e.seed)}};
}

// Model vs measurement for the best trial of each algorithm.
std::vector<std::filesystem::path> fit_figures(const std::filesystem::path& dir, const Problem& problem,
                                               const std::vector<AlgorithmSummary>& summaries,
                                               const ReportContext& ctx) {
  std::vector<std::filesystem::path> scripts;
  const auto* model = dynamic_cast<const SignalModelProblem*>(&problem);
  if (!model) return scripts;
  for (const auto& s : summaries) {
    if (s.best_trial < 0) continue;
    const Eigen::VectorXd x = Eigen::Map<const Eigen::VectorXd>(s.best_x.data(), s.best_x.size());
    auto made = write_fit_figures(dir, s.label, model->time(), model->input(), model->measured(),
                                  model->simulate(x), model->segments(), ctx);
    scripts.insert(scripts.end(), made.begin(), made.end());
  }
  return scripts;
}

}  // namespace

std::string describe_budget(const Budget& b) {
  std::vector<std::string> parts;
  auto add = [&](auto v, const char* unit) {
    std::ostringstream os;
    os << v << unit;
    parts.push_back(os.str());
  };
  if (b.evaluations) add(*b.evaluations, " evaluations");
  if (b.iterations) add(*b.iterations, " iterations");
  if (b.seconds) add(*b.seconds, " s");
  if (b.target) add(*b.target, " target fitness");
  std::string out;
  for (const auto& p : parts) out += (out.empty() ? "" : " or ") + p;
  return out;
}

WrittenReport write_report(const std::filesystem::path& dir, const Experiment& experiment,
                           const Problem& problem,
                           const std::vector<std::vector<TrialResult>>& results, int threads,
                           const std::string& reference) {
  WrittenReport out;
  const ReportContext ctx = report_context(experiment, problem, results);
  out.summaries = summarize_all(experiment, problem, results);
  write_file_atomic(dir / "summary.json", summary_json(dir, experiment, problem, out.summaries, threads).dump(2) + "\n");
  write_tables(dir, out.summaries, ctx);
  const auto statistics = campaign_statistics(experiment, results, reference, ctx.noise_floor);
  write_stats_tables(dir, statistics, ctx);
  write_results_readme(dir,
                       "Made by `hystbench run` (or `report`) from the experiment `" + experiment.name +
                           "` in `summary.json`, whose trials are in `trials.jsonl`.",
                       {{"table", table_method(ctx)}, {"stats", stats_method(statistics)}});

  std::vector<ConvergenceCurve> curves;
  for (std::size_t a = 0; a < results.size(); ++a)
    curves.push_back(convergence_curve(experiment.algorithms[a].label, results[a]));
  write_convergence_csv(dir / "convergence.csv", curves);

  std::vector<std::filesystem::path> scripts{write_convergence_figure(dir, curves, ctx)};
  scripts.push_back(write_boxplot_figure(dir, experiment, results, ctx));
  if (const auto ecdf = write_ecdf_figure(dir, experiment, results, statistics.target, ctx))
    scripts.push_back(*ecdf);
  const auto fits = fit_figures(dir, problem, out.summaries, ctx);
  scripts.insert(scripts.end(), fits.begin(), fits.end());
  out.figures = render_figures(dir, scripts, out.note);
  if (!statistics.target)
    out.note += std::string(out.note.empty() ? "" : "\n") +
                "No runtime ECDF: no target fitness is known (set budget.target, or use data "
                "whose noise floor is known).";
  for (const char* f : {"summary.json", "trials.jsonl", "README.md", "table.md", "table.tex", "table.csv",
                        "stats.md", "stats.tex", "stats.csv", "convergence.csv", "boxplot.csv"})
    out.files.push_back(dir / f);
  if (statistics.target) out.files.push_back(dir / "ecdf.csv");
  return out;
}

}  // namespace hystbench
