#include "framework/report/tables.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "framework/core/text.hpp"
#include "framework/io/atomic_file.hpp"
#include "framework/io/csv_format.hpp"
#include "framework/report/cell_table.hpp"
#include "framework/report/table_format.hpp"

namespace hystbench {
namespace {

using namespace table;

struct FitnessColumn {
  const char* markdown;
  const char* latex;
  double AlgorithmSummary::*field;
};

// Lower is better in every fitness column (a smaller spread is better too),
// so the bold cell of each column is its minimum.
constexpr std::array<FitnessColumn, 6> kFitnessColumns{{
    {"Best fitness value", "Best", &AlgorithmSummary::best},
    {"f_avg", "$f_{\\mathrm{avg}}$", &AlgorithmSummary::mean},
    {"f_max", "$f_{\\max}$", &AlgorithmSummary::max},
    {"f_min", "$f_{\\min}$", &AlgorithmSummary::min},
    {"f_std", "$f_{\\mathrm{std}}$", &AlgorithmSummary::std},
    {"Median", "Median", &AlgorithmSummary::median},
}};

// The fitness columns of the layout: "Best fitness value" is f_min by
// definition (the lowest final fitness of the successful trials), so only
// the seed's layout, which reproduces MEDE's Table 1, shows both.
std::vector<FitnessColumn> fitness_columns(const ReportContext& ctx) {
  return {kFitnessColumns.begin() + (ctx.seed_table_layout ? 0 : 1), kFitnessColumns.end()};
}

double column_minimum(const std::vector<AlgorithmSummary>& rows, double AlgorithmSummary::*field) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& r : rows)
    if (std::isfinite(r.*field)) best = std::min(best, r.*field);
  return best;
}

std::vector<std::string> header_cells(const ReportContext& ctx, Format f) {
  std::vector<std::string> cells{"Algorithm"};
  for (const auto& c : fitness_columns(ctx))
    cells.push_back(f == Format::Markdown ? c.markdown : c.latex);
  for (const char* name : {"Iterations", "Evaluations", "Failed"}) cells.push_back(name);
  return cells;
}

std::vector<std::vector<std::string>> body_cells(const std::vector<AlgorithmSummary>& rows,
                                                 const ReportContext& ctx, Format f) {
  const auto columns = fitness_columns(ctx);
  std::vector<std::string> minimum(columns.size());
  for (std::size_t c = 0; c < columns.size(); ++c) {
    const double m = column_minimum(rows, columns[c].field);
    if (std::isfinite(m)) minimum[c] = format_fitness(m, f);
  }
  std::vector<std::vector<std::string>> body;
  for (const auto& r : rows) {
    std::vector<std::string> cells{escape(r.label, f)};
    for (std::size_t c = 0; c < columns.size(); ++c)
      cells.push_back(bold_if_best(format_fitness(r.*columns[c].field, f), minimum[c], f));
    cells.push_back(format_count(r.mean_iterations, f));
    cells.push_back(format_count(r.mean_evaluations, f));
    cells.push_back(std::to_string(r.failed) + "/" + std::to_string(r.trials));
    body.push_back(std::move(cells));
  }
  return body;
}

// What a reader of the table alone needs to know about the run.
std::string caption(const ReportContext& ctx, Format f) {
  const bool md = f == Format::Markdown;
  const auto name = [&](const std::string& s) {
    return md ? "`" + s + "`" : "\\texttt{" + escape_latex(s) + "}";
  };
  std::string text = "Experiment " + name(ctx.experiment) + ", problem " + name(ctx.problem) +
                     ": " + std::to_string(ctx.trials) + " trials per algorithm";
  if (!ctx.budget.empty()) text += ", budget " + escape(ctx.budget, f);
  text += ", seed " + std::to_string(ctx.seed) + ".";
  if (ctx.noise_floor) text += " Noise floor " + format_fitness(*ctx.noise_floor, f) + ".";
  text += " Final fitness over the successful trials; bold: lowest per column.";
  return ctx.seed_table_layout ? text + " Best and " + (md ? "f_min" : "$f_{\\min}$") + " coincide by definition."
                               : text;
}

// Why trials failed, under the table: a failure is a result to explain,
// not a row to hide.
std::string failure_notes(const std::vector<AlgorithmSummary>& rows) {
  std::string out;
  for (const auto& r : rows)
    if (r.failed > 0)
      out += "- " + r.label + ": " + std::to_string(r.failed) + " of " + std::to_string(r.trials) +
             " trials failed; first, " + r.first_failure + "\n";
  return out.empty() ? out : "\nFailed trials (every message is in `trials.jsonl`):\n" + out;
}

}  // namespace

std::string table_markdown(const std::vector<AlgorithmSummary>& rows, const ReportContext& ctx) {
  const table::CellTable t{caption(ctx, Format::Markdown), "", header_cells(ctx, Format::Markdown),
                           body_cells(rows, ctx, Format::Markdown)};
  return table::markdown(t) + failure_notes(rows);
}

std::string table_latex(const std::vector<AlgorithmSummary>& rows, const ReportContext& ctx) {
  const auto header = header_cells(ctx, Format::Latex);
  std::string out =
      "% Requires \\usepackage{booktabs}. Nine or ten columns fill a one-column page; in a\n"
      "% two-column paper use table* (or wrap the tabular in \\resizebox{\\linewidth}{!}{...}).\n"
      "\\begin{table}[htbp]\n  \\centering\n";
  out += "  \\caption{" + caption(ctx, Format::Latex) + "}\n";
  out += "  \\label{tab:" + label_key(ctx.experiment) + "}\n";
  out += "  \\footnotesize\n  \\setlength{\\tabcolsep}{3pt}\n";
  out += "  \\begin{tabular}{l" + std::string(header.size() - 1, 'r') + "}\n    \\toprule\n";
  out += "    " + join(header, " & ") + " \\\\\n    \\midrule\n";
  for (const auto& cells : body_cells(rows, ctx, Format::Latex))
    out += "    " + join(cells, " & ") + " \\\\\n";
  out += "    \\bottomrule\n  \\end{tabular}\n\\end{table}\n";
  return out;
}

std::string table_csv(const std::vector<AlgorithmSummary>& rows) {
  std::string out =
      "algorithm,best,f_avg,f_max,f_min,f_std,median,iterations,evaluations,failed,trials\n";
  // Appended piece by piece: `"," + temporary` trips a false -Wrestrict in GCC 12.
  const auto cell = [&out](const std::string& text) { out.append(",").append(text); };
  for (const auto& r : rows) {
    out += csv_field(r.label);
    for (double v : {r.best, r.mean, r.max, r.min, r.std, r.median, r.mean_iterations,
                     r.mean_evaluations})
      cell(csv_number(v));
    cell(std::to_string(r.failed));
    cell(std::to_string(r.trials));
    out += '\n';
  }
  return out;
}

std::string table_method(const ReportContext& ctx) {
  std::string text =
      "One row per algorithm, over its trials' final fitness (the best value a trial found): f_avg, "
      "f_max, f_min, f_std and Median over the trials that did not fail; Iterations and Evaluations "
      "are means over them; Failed counts the failed trials (their messages are in `trials.jsonl`). "
      "The lowest printed value of each fitness column is in bold, ties included.";
  if (ctx.noise_floor)
    text += " The noise floor is the SSE of the true parameters on these data: a fit there has "
            "found all the data can tell.";
  text += ctx.seed_table_layout
              ? " This table follows MEDE's Table 1 (`\"table_layout\": \"seed\"`): its Best fitness "
                "value is the lowest final fitness of any trial, which is f_min by definition."
              : " MEDE's Table 1 also prints a Best fitness value, which is f_min by definition; "
                "`\"table_layout\": \"seed\"` in the experiment adds that column.";
  return text + " `table.csv` holds every statistic at full precision, Best among them.";
}

void write_tables(const std::filesystem::path& dir, const std::vector<AlgorithmSummary>& rows,
                  const ReportContext& ctx) {
  write_file_atomic(dir / "table.md", table_markdown(rows, ctx));
  write_file_atomic(dir / "table.tex", table_latex(rows, ctx));
  write_file_atomic(dir / "table.csv", table_csv(rows));
}

}  // namespace hystbench
