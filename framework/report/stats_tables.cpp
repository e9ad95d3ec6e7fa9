#include "framework/report/stats_tables.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "framework/core/text.hpp"
#include "framework/io/atomic_file.hpp"
#include "framework/io/csv_format.hpp"
#include "framework/report/cell_table.hpp"
#include "framework/report/table_format.hpp"
#include "framework/stats/rank_sum_exact.hpp"

namespace hystbench {
namespace {

using namespace table;

std::string percent(double fraction, Format f) {
  return std::to_string(std::lround(100 * fraction)) + (f == Format::Latex ? "\\%" : " %");
}

std::string mark_cell(const AlgorithmStatistics& r, Format f) {
  if (r.reference) return "ref.";
  if (r.mark == '-') return f == Format::Latex ? "$-$" : "-";
  return std::string(1, r.mark);
}

std::vector<std::string> header_cells(Format f) {
  const bool md = f == Format::Markdown;
  std::vector<std::string> cells{"Algorithm", "Mark", md ? "p_Holm" : "$p_{\\mathrm{Holm}}$",
                                 "Success", "ERT"};
  for (double q : kSnapshotFractions)
    cells.push_back(md ? "f@" + percent(q, f) : "$f_{" + percent(q, f) + "}$");
  return cells;
}

// The bold cell of a column: the lowest value, or the highest for the
// success rate. NaN (no value) is never bold, and a column whose values all
// tie (0/30 everywhere) has no best: NaN.
double best_of(const std::vector<AlgorithmStatistics>& rows,
               const std::function<double(const AlgorithmStatistics&)>& value, bool highest) {
  const double none = std::numeric_limits<double>::quiet_NaN();
  double best = none;
  bool all_tie = true;
  for (const auto& r : rows) {
    const double v = value(r);
    if (std::isnan(v)) continue;
    if (!std::isnan(best) && v != best) all_tie = false;
    if (std::isnan(best) || (highest ? v > best : v < best)) best = v;
  }
  return all_tie && rows.size() > 1 ? none : best;
}

// A column of the table: the value that ranks a row and the cell that shows it.
struct Column {
  std::function<double(const AlgorithmStatistics&)> value;
  bool highest;  // higher is better (the success rate)
  std::function<std::string(const AlgorithmStatistics&)> print;
};

// Row r's cell, bold when it prints as the best row's cell does.
std::string column_cell(const AlgorithmStatistics& r, const std::vector<AlgorithmStatistics>& rows,
                        const Column& c, Format f) {
  const double best = best_of(rows, c.value, c.highest);
  std::string best_text;
  for (const auto& x : rows)
    if (!std::isnan(best) && c.value(x) == best) best_text = c.print(x);
  return bold_if_best(c.print(r), best_text, f);
}

std::vector<std::string> row_cells(const AlgorithmStatistics& r, const CampaignStatistics& s,
                                   Format f) {
  std::vector<std::string> cells{escape(r.label, f), mark_cell(r, f),
                                 std::isnan(r.p_holm) ? non_finite(r.p_holm, f)
                                                      : format_fitness(r.p_holm, f)};
  const Column success{[](const AlgorithmStatistics& x) { return x.success_rate; }, true,
                       [f](const AlgorithmStatistics& x) {
                         return std::isnan(x.success_rate)
                                    ? non_finite(x.success_rate, f)
                                    : std::to_string(x.successes) + "/" + std::to_string(x.trials);
                       }};
  const Column ert{[](const AlgorithmStatistics& x) { return x.ert; }, false,
                   [f](const AlgorithmStatistics& x) { return format_count(x.ert, f); }};
  cells.push_back(column_cell(r, s.rows, success, f));
  cells.push_back(column_cell(r, s.rows, ert, f));
  for (std::size_t i = 0; i < r.snapshot_medians.size(); ++i) {
    const Column at{[i](const AlgorithmStatistics& x) { return x.snapshot_medians[i]; }, false,
                    [i, f](const AlgorithmStatistics& x) {
                      return format_fitness(x.snapshot_medians[i], f);
                    }};
    cells.push_back(column_cell(r, s.rows, at, f));
  }
  return cells;
}

// "+/=/-" counts of the marks, printed under the table (docs/algorithms.md#rank-sum-test).
std::string mark_counts(const CampaignStatistics& s) {
  int plus = 0, same = 0, minus = 0;
  for (const auto& r : s.rows) {
    if (r.reference) continue;
    (r.mark == '+' ? plus : r.mark == '-' ? minus : same) += 1;
  }
  return std::to_string(plus) + "/" + std::to_string(same) + "/" + std::to_string(minus);
}

std::string run_sentence(const ReportContext& ctx, Format f) {
  const bool md = f == Format::Markdown;
  const auto name = [&](const std::string& s) {
    return md ? "`" + s + "`" : "\\texttt{" + escape_latex(s) + "}";
  };
  std::string text = "Experiment " + name(ctx.experiment) + ", data " + name(ctx.problem) + ": " +
                     std::to_string(ctx.trials) + " trials per algorithm";
  if (!ctx.budget.empty()) text += ", budget " + escape(ctx.budget, f);
  return text + ", seed " + std::to_string(ctx.seed) + ".";
}

std::string mark_sentence(const CampaignStatistics& s, Format f) {
  const bool tex = f == Format::Latex;
  const std::string minus = tex ? "$-$" : "-";
  return " Mark: two-sided Wilcoxon rank-sum test of the final fitness of the reference " +
         escape(s.reference, f) +
         (s.reference_chosen ? " (chosen by the user)" : " (the lowest median final fitness)") +
         " against each algorithm at " + significance_level(s.alpha, f) +
         ", Holm-corrected over the " +
         std::to_string(s.rows.size() - 1) + (s.rows.size() == 2 ? " comparison" : " comparisons") +
         ": + the reference is significantly "
         "better, " + minus + " significantly worse, = no significant difference; " +
         (tex ? "$p_{\\mathrm{Holm}}$" : "p_Holm") + " is the adjusted p-value; counts " + mark_counts(s) + " (+/=/" + minus + ").";
}

// Where the raw p-values came from: the rule, and which side of it this
// campaign's comparisons fell on.
std::string p_value_sentence(const CampaignStatistics& s, Format f) {
  int exact = 0, normal = 0;
  for (const auto& r : s.rows)
    if (!r.reference && !std::isnan(r.p_holm)) (r.p_exact ? exact : normal) += 1;
  std::string here;
  if (exact > 0 && normal == 0) here = " (here exact throughout)";
  if (exact == 0 && normal > 0) here = " (here normal throughout)";
  if (exact > 0 && normal > 0)
    here = " (here exact for " + std::to_string(exact) + ", normal for " + std::to_string(normal) +
           (normal == 1 ? " comparison)" : " comparisons)");
  const std::string at_most = f == Format::Latex ? "$\\le$ " : "≤ ";
  return " p: two-sided rank-sum test, exact (permutation distribution of the rank sum, ties at "
         "their mid-ranks) when both algorithms have " + at_most +
         std::to_string(stats::kExactRankSumMaxSize) +
         " trials, normal approximation with tie and continuity correction above" + here +
         "; Holm-adjusted.";
}

std::string runtime_sentence(const CampaignStatistics& s, Format f) {
  std::string text;
  if (s.target)
    text = " Success: trials that reached the target fitness " + format_fitness(*s.target, f) +
           " (" + escape(s.target_origin, f) + "); ERT: expected running time to it in evaluations "
           "(the evaluations of all trials, each up to the target when it reached it, divided by "
           "the number of successes; infinite without one).";
  else
    text = " No target fitness is known (no budget target, no noise floor): no success rate "
           "or ERT.";
  // Named as the column headers name it.
  const std::string snapshot = f == Format::Markdown ? "f@q" : "$f_q$";
  std::string fractions;
  for (double q : kSnapshotFractions)
    fractions += (fractions.empty() ? "" : ", ") + percent(q, f);
  if (s.budget && s.budget_from_trials)
    text += " " + snapshot + ": median best-so-far fitness after " + fractions + " of " +
            std::to_string(*s.budget) + " evaluations, the most any trial used (the budget " +
            "counts iterations or time).";
  else if (s.budget)
    text += " " + snapshot + ": median best-so-far fitness after " + fractions + " of the " +
            std::to_string(*s.budget) + "-evaluation budget.";
  else
    text += " No evaluation budget: no fixed-budget values.";
  return text + " Best printed value per column in bold, ties included.";
}

// The caption says what the marks and columns are; how they are computed is
// in stats_method(), for the folder's README.md.
std::string caption(const CampaignStatistics& s, const ReportContext& ctx, Format f) {
  const bool tex = f == Format::Latex;
  std::string text = run_sentence(ctx, f) + " Marks: rank-sum test against " + escape(s.reference, f) +
                     ", Holm-corrected at " + significance_level(s.alpha, f) + " (+ " + escape(s.reference, f) +
                     " better, " + (tex ? "$-$" : "−") + " worse, = no difference).";
  if (s.target) text += " Success, ERT: reaching " + format_fitness(*s.target, f) + ".";
  return text + " Bold: best per column.";
}

}  // namespace

std::string stats_markdown(const CampaignStatistics& s, const ReportContext& ctx) {
  table::CellTable t{caption(s, ctx, Format::Markdown), "", header_cells(Format::Markdown), {}};
  for (const auto& r : s.rows) t.rows.push_back(row_cells(r, s, Format::Markdown));
  return table::markdown(t) + "\n+/=/-: " + mark_counts(s) + "\n";
}

std::string stats_latex(const CampaignStatistics& s, const ReportContext& ctx) {
  const auto header = header_cells(Format::Latex);
  std::string out = "% Requires \\usepackage{booktabs}.\n\\begin{table}[htbp]\n  \\centering\n";
  out += "  \\caption{" + caption(s, ctx, Format::Latex) + "}\n";
  out += "  \\label{tab:" + label_key(ctx.experiment) + "-stats}\n";
  out += "  \\footnotesize\n  \\setlength{\\tabcolsep}{3pt}\n";
  out += "  \\begin{tabular}{l" + std::string(header.size() - 1, 'r') + "}\n    \\toprule\n";
  out += "    " + join(header, " & ") + " \\\\\n    \\midrule\n";
  for (const auto& r : s.rows) out += "    " + join(row_cells(r, s, Format::Latex), " & ") + " \\\\\n";
  out += "    \\midrule\n    $+/=/-$ & \\multicolumn{" + std::to_string(header.size() - 1) +
         "}{l}{" + mark_counts(s) + "} \\\\\n";
  out += "    \\bottomrule\n  \\end{tabular}\n\\end{table}\n";
  return out;
}

std::string stats_method(const CampaignStatistics& s) {
  const std::string text = mark_sentence(s, Format::Markdown) + p_value_sentence(s, Format::Markdown) +
                           runtime_sentence(s, Format::Markdown);
  return text.substr(text.find_first_not_of(' '));
}

std::string stats_csv(const CampaignStatistics& s) {
  std::string out = "algorithm,reference,mark,p_holm,successes,trials,success_rate,ert";
  for (double q : kSnapshotFractions)
    out.append(",f_at_").append(std::to_string(std::lround(100 * q))).append("pct");
  out += '\n';
  const auto cell = [&out](const std::string& text) { out.append(",").append(text); };
  for (const auto& r : s.rows) {
    out += csv_field(r.label);
    cell(r.reference ? "1" : "0");
    cell(r.reference ? "" : std::string(1, r.mark));
    cell(csv_number(r.p_holm));
    cell(std::isnan(r.success_rate) ? "" : std::to_string(r.successes));
    cell(std::to_string(r.trials));
    cell(csv_number(r.success_rate));
    cell(csv_number(r.ert));
    for (double v : r.snapshot_medians) cell(csv_number(v));
    out += '\n';
  }
  return out;
}

void write_stats_tables(const std::filesystem::path& dir, const CampaignStatistics& s,
                        const ReportContext& ctx) {
  write_file_atomic(dir / "stats.md", stats_markdown(s, ctx));
  write_file_atomic(dir / "stats.tex", stats_latex(s, ctx));
  write_file_atomic(dir / "stats.csv", stats_csv(s));
}

}  // namespace hystbench
