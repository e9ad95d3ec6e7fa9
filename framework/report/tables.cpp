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

double column_minimum(const std::vector<AlgorithmSummary>& rows, double AlgorithmSummary::*field) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& r : rows)
    if (std::isfinite(r.*field)) best = std::min(best, r.*field);
  return best;
}

std::vector<std::string> header_cells(Format f) {
  std::vector<std::string> cells{"Algorithm"};
  for (const auto& c : kFitnessColumns)
    cells.push_back(f == Format::Markdown ? c.markdown : c.latex);
  for (const char* name : {"Iterations", "Evaluations", "Failed"}) cells.push_back(name);
  return cells;
}

std::vector<std::vector<std::string>> body_cells(const std::vector<AlgorithmSummary>& rows,
                                                 Format f) {
  std::array<std::string, kFitnessColumns.size()> minimum;
  for (std::size_t c = 0; c < kFitnessColumns.size(); ++c) {
    const double m = column_minimum(rows, kFitnessColumns[c].field);
    if (std::isfinite(m)) minimum[c] = format_fitness(m, f);
  }
  std::vector<std::vector<std::string>> body;
  for (const auto& r : rows) {
    std::vector<std::string> cells{escape(r.label, f)};
    for (std::size_t c = 0; c < kFitnessColumns.size(); ++c) {
      cells.push_back(bold_if_best(format_fitness(r.*kFitnessColumns[c].field, f), minimum[c], f));
    }
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
  if (ctx.noise_floor) {
    text += " Noise floor (SSE of the true parameters): " +
            format_fitness(*ctx.noise_floor, f) + ".";
  }
  return text + " Fitness statistics over the successful trials; lowest printed value per column "
                "in bold, ties included.";
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
  const table::CellTable t{caption(ctx, Format::Markdown), "", header_cells(Format::Markdown),
                           body_cells(rows, Format::Markdown)};
  return table::markdown(t) + failure_notes(rows);
}

std::string table_latex(const std::vector<AlgorithmSummary>& rows, const ReportContext& ctx) {
  const auto header = header_cells(Format::Latex);
  std::string out =
      "% Requires \\usepackage{booktabs}. Ten columns fill a one-column page; in a\n"
      "% two-column paper use table* (or wrap the tabular in \\resizebox{\\linewidth}{!}{...}).\n"
      "\\begin{table}[htbp]\n  \\centering\n";
  out += "  \\caption{" + caption(ctx, Format::Latex) + "}\n";
  out += "  \\label{tab:" + label_key(ctx.experiment) + "}\n";
  out += "  \\footnotesize\n  \\setlength{\\tabcolsep}{3pt}\n";
  out += "  \\begin{tabular}{l" + std::string(header.size() - 1, 'r') + "}\n    \\toprule\n";
  out += "    " + join(header, " & ") + " \\\\\n    \\midrule\n";
  for (const auto& cells : body_cells(rows, Format::Latex))
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

void write_tables(const std::filesystem::path& dir, const std::vector<AlgorithmSummary>& rows,
                  const ReportContext& ctx) {
  write_file_atomic(dir / "table.md", table_markdown(rows, ctx));
  write_file_atomic(dir / "table.tex", table_latex(rows, ctx));
  write_file_atomic(dir / "table.csv", table_csv(rows));
}

}  // namespace hystbench
