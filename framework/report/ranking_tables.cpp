#include "framework/report/ranking_tables.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "framework/core/text.hpp"
#include "framework/io/atomic_file.hpp"
#include "framework/io/csv_format.hpp"
#include "framework/io/json_number.hpp"
#include "framework/report/cell_table.hpp"
#include "framework/report/gnuplot_script.hpp"
#include "framework/report/ranking_figure.hpp"
#include "framework/report/results_readme.hpp"
#include "framework/report/table_format.hpp"

namespace hystbench {
namespace {

using namespace table;

std::string p_value(double p, Format f) {
  return std::isnan(p) ? non_finite(p, f) : format_fitness(p, f);
}

// The mark from the control's point of view, as in the rank-sum tables.
char control_mark(const stats::ControlComparison& c) {
  if (!c.rejected) return '=';
  return c.z > 0 ? '+' : '-';
}

const stats::ControlComparison* comparison_of(const FriedmanRanking& r, int j) {
  for (const auto& c : r.versus_control)
    if (c.algorithm == j) return &c;
  return nullptr;  // the control itself
}

std::string mark_cell(const FriedmanRanking& r, int j, Format f) {
  const auto* c = comparison_of(r, j);
  if (!c) return "ctrl.";
  const char m = control_mark(*c);
  return m == '-' && f == Format::Latex ? "$-$" : std::string(1, m);
}

std::vector<std::string> header_cells(const FriedmanRanking& r, Format f) {
  const bool md = f == Format::Markdown;
  std::vector<std::string> cells{"Algorithm"};
  for (const auto& b : r.blocks) cells.push_back(escape(b, f));
  for (const char* c : {"Avg. rank", "Mark"}) cells.push_back(c);
  cells.push_back(md ? "p_Holm" : "$p_{\\mathrm{Holm}}$");
  return cells;
}

std::vector<std::string> row_cells(const FriedmanRanking& r, int j, Format f) {
  std::vector<std::string> cells{escape(r.labels[j], f)};
  for (const auto& ranks : r.ranks) cells.push_back(format_count(ranks[j], f));
  const auto& avg = r.test.average_ranks;
  const double best = *std::min_element(avg.begin(), avg.end());
  const std::string rank = format_fitness(avg[j], f);
  cells.push_back(bold_if_best(rank, format_fitness(best, f), f));
  cells.push_back(mark_cell(r, j, f));
  const auto* c = comparison_of(r, j);
  cells.push_back(c ? p_value(c->p_holm, f) : non_finite(std::nan(""), f));
  return cells;
}

// "10 trials" or "5-10 trials" when the folders differ.
std::string trials_text(const FriedmanRanking& r) {
  const auto [lo, hi] = std::minmax_element(r.trials.begin(), r.trials.end());
  return (*lo == *hi ? std::to_string(*lo) : std::to_string(*lo) + "–" + std::to_string(*hi)) +
         " trials";
}

std::string budget_text(const FriedmanRanking& r) {
  const bool same = std::all_of(r.budgets.begin(), r.budgets.end(),
                                [&](const std::string& b) { return b == r.budgets[0]; });
  return same ? "budget " + r.budgets[0] : "budgets differ between the data sets (ranks.csv)";
}

std::string statistics_sentence(const FriedmanRanking& r, Format f) {
  const bool tex = f == Format::Latex;
  const auto& t = r.test;
  const int k = t.algorithms, n = t.blocks;
  std::string s = " Friedman " + std::string(tex ? "$\\chi^2_F$" : "χ²_F") + " = " +
                  format_fitness(t.chi2, f) + " (" + std::to_string(k - 1) + " d.o.f., p = " +
                  p_value(t.chi2_p, f) + "); Iman–Davenport " + (tex ? "$F_F$" : "F_F") + " = " +
                  (std::isinf(t.f) ? non_finite(t.f, f) : format_fitness(t.f, f)) + " (F(" +
                  std::to_string(k - 1) + ", " + std::to_string((k - 1) * (n - 1)) +
                  "), p = " + p_value(t.f_p, f) + ").";
  if (r.critical_difference)
    s += " Nemenyi critical difference at " + significance_level(0.05, f) + ": CD = " +
         format_fitness(*r.critical_difference, f) +
         "; two average ranks further apart differ significantly.";
  else
    s += " No Nemenyi CD: its table stops at 10 algorithms.";
  return s;
}

std::string control_sentence(const FriedmanRanking& r, Format f) {
  const std::string minus = f == Format::Latex ? "$-$" : "-";
  return " Mark: each algorithm's average rank against the control " + escape(r.labels[r.control], f) +
         (r.control_chosen ? " (chosen by the user)" : " (the best average rank)") +
         ", z-test with Holm's correction over " + std::to_string(r.labels.size() - 1) +
         " comparisons at " + significance_level(0.05, f) +
         ": + the control ranks significantly better, " + minus +
         " significantly worse, = no significant difference. Best average rank in bold.";
}

// Short, for a paper; the tests and their statistics are in ranking_method().
std::string caption(const FriedmanRanking& r, Format f) {
  const bool tex = f == Format::Latex;
  std::string text = "Friedman average ranks (1 = best) of " + std::to_string(r.labels.size()) +
                     " algorithms over " + std::to_string(r.blocks.size()) + " data sets, by " +
                     to_string(r.statistic) + " final fitness; p = " + p_value(r.test.f_p, f) +
                     " (Iman–Davenport).";
  if (r.critical_difference) text += " Nemenyi CD = " + format_fitness(*r.critical_difference, f) + ".";
  return text + " Marks: against " + escape(r.labels[r.control], f) + ", Holm-corrected (+ better, " +
         (tex ? "$-$" : "−") + " worse). Bold: best.";
}

std::string data_set_list(const FriedmanRanking& r) {
  std::string out = "\nData sets (results folders) and their problems:\n\n";
  for (std::size_t i = 0; i < r.blocks.size(); ++i)
    out += "- `" + r.blocks[i] + "`: `" + r.problems[i] + "`, " + r.budgets[i] + "\n";
  return out;
}

}  // namespace

std::string ranking_markdown(const FriedmanRanking& r) {
  table::CellTable t{caption(r, Format::Markdown), "", header_cells(r, Format::Markdown), {}};
  for (int j = 0; j < int(r.labels.size()); ++j) t.rows.push_back(row_cells(r, j, Format::Markdown));
  return table::markdown(t) + data_set_list(r);
}

std::string ranking_latex(const FriedmanRanking& r) {
  const auto header = header_cells(r, Format::Latex);
  std::string out = "% Requires \\usepackage{booktabs}. One column per data set: with many or long\n"
                    "% data-set names use table* or \\resizebox{\\linewidth}{!}{...}.\n"
                    "\\begin{table}[htbp]\n  \\centering\n";
  out += "  \\caption{" + caption(r, Format::Latex) + "}\n  \\label{tab:friedman-ranks}\n";
  out += "  \\footnotesize\n  \\setlength{\\tabcolsep}{3pt}\n";
  out += "  \\begin{tabular}{l" + std::string(header.size() - 1, 'r') + "}\n    \\toprule\n";
  out += "    & \\multicolumn{" + std::to_string(r.blocks.size()) +
         "}{c}{Rank per data set} \\\\\n    \\cmidrule(lr){2-" +
         std::to_string(r.blocks.size() + 1) + "}\n";
  out += "    " + join(header, " & ") + " \\\\\n    \\midrule\n";
  for (int j = 0; j < int(r.labels.size()); ++j)
    out += "    " + join(row_cells(r, j, Format::Latex), " & ") + " \\\\\n";
  return out + "    \\bottomrule\n  \\end{tabular}\n\\end{table}\n";
}

std::string ranking_csv(const FriedmanRanking& r) {
  std::string out = "algorithm,average_rank,control,z,p,p_holm,mark";
  for (const auto& b : r.blocks) out += "," + csv_field("rank:" + b) + "," + csv_field("value:" + b);
  out += '\n';
  for (int j = 0; j < int(r.labels.size()); ++j) {
    const auto* c = comparison_of(r, j);
    out += csv_field(r.labels[j]) + "," + csv_number(r.test.average_ranks[j]) + "," +
           (c ? "0" : "1") + "," + (c ? csv_number(c->z) : "") + "," + (c ? csv_number(c->p) : "") +
           "," + (c ? csv_number(c->p_holm) : "") + "," + (c ? std::string(1, control_mark(*c)) : "");
    for (std::size_t i = 0; i < r.blocks.size(); ++i)
      out += "," + csv_number(r.ranks[i][j]) + "," + csv_number(r.values[i][j]);
    out += '\n';
  }
  return out;
}

nlohmann::json ranking_json(const FriedmanRanking& r) {
  return {{"statistic", to_string(r.statistic)},
          {"data_sets", r.blocks},
          {"problems", r.problems},
          {"algorithms", r.labels},
          {"average_ranks", r.test.average_ranks},
          {"chi2_F", number_or_null(r.test.chi2)},
          {"chi2_p", number_or_null(r.test.chi2_p)},
          {"iman_davenport_F", number_or_null(r.test.f)},
          {"iman_davenport_p", number_or_null(r.test.f_p)},
          {"nemenyi_cd_0.05", r.critical_difference ? number_or_null(*r.critical_difference) : nullptr},
          {"control", r.labels[r.control]}};
}

std::string ranking_method(const FriedmanRanking& r) {
  const std::string text = "In each data set the algorithms are ranked by the " + to_string(r.statistic) +
                           " final fitness of their " + trials_text(r) + " (ties share the average rank); " +
                           budget_text(r) + "." + statistics_sentence(r, Format::Markdown) +
                           control_sentence(r, Format::Markdown);
  return text + data_set_list(r);
}

std::vector<std::filesystem::path> write_ranking(const std::filesystem::path& dir,
                                                 const FriedmanRanking& r) {
  write_file_atomic(dir / "ranks.md", ranking_markdown(r));
  write_file_atomic(dir / "ranks.tex", ranking_latex(r));
  write_file_atomic(dir / "ranks.csv", ranking_csv(r));
  write_file_atomic(dir / "ranks.json", ranking_json(r).dump(2) + "\n");
  write_results_readme(dir, "Made by `hystbench rank` from the results folders listed below.",
                       {{"ranks", ranking_method(r)}});
  return {dir / "README.md", dir / "ranks.md", dir / "ranks.tex", dir / "ranks.csv", dir / "ranks.json",
          write_ranking_figure(dir, r)};
}

}  // namespace hystbench
