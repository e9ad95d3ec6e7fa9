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

namespace hystbench {
namespace {

enum class Format { Markdown, Latex };

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

std::string printf_string(const char* format, double x, int precision = -1) {
  char buf[64];
  if (precision < 0)
    std::snprintf(buf, sizeof buf, format, x);
  else
    std::snprintf(buf, sizeof buf, format, precision, x);
  return buf;
}

std::string non_finite(double x, Format f) {
  const bool md = f == Format::Markdown;
  if (std::isnan(x)) return md ? "—" : "--";
  const std::string sign = x < 0 ? "-" : "";
  return md ? sign + "∞" : "$" + sign + "\\infty$";
}

// Four significant digits. Rounding first (through %.3e) decides the
// notation from the printed value, so 9999.7 becomes 1.000e+04, not 10000.
std::string format_fitness(double x, Format f) {
  if (!std::isfinite(x)) return non_finite(x, f);
  if (x == 0.0) return "0";
  const std::string sci = printf_string("%.3e", x);
  const auto e_pos = sci.find('e');
  const int exponent = std::atoi(sci.c_str() + e_pos + 1);
  if (exponent < -3 || exponent >= 4) {
    if (f == Format::Markdown) return sci;
    // std::string("$") first: `"$" + temporary` trips a false -Wrestrict in GCC 12.
    return std::string("$") + sci.substr(0, e_pos) + "\\times10^{" + std::to_string(exponent) +
           "}$";
  }
  const std::string fixed = printf_string("%.*f", x, 3 - exponent);
  return (f == Format::Latex && x < 0) ? "$" + fixed + "$" : fixed;
}

// Mean iterations and evaluations per trial: whole numbers stay whole.
std::string format_count(double x, Format f) {
  if (!std::isfinite(x)) return non_finite(x, f);
  if (x == std::round(x)) return printf_string("%.0f", x);
  return printf_string("%.1f", x);
}

std::string bold(const std::string& cell, Format f) {
  if (f == Format::Markdown) return "**" + cell + "**";
  // \textbf does not reach into math mode; \boldmath does.
  const bool math = cell.find('$') != std::string::npos;
  return std::string("\\textbf{") + (math ? "\\boldmath" : "") + cell + "}";
}

std::string escape_latex(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '_': case '%': case '&': case '#': case '$': case '{': case '}':
        out += '\\';
        out += c;
        break;
      case '\\': out += "\\textbackslash{}"; break;
      case '~': out += "\\textasciitilde{}"; break;
      case '^': out += "\\textasciicircum{}"; break;
      default: out += c;
    }
  }
  return out;
}

std::string escape_markdown(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '|' || c == '*' || c == '_' || c == '`' || c == '\\') out += '\\';
    out += c;
  }
  return out;
}

std::string escape(const std::string& s, Format f) {
  return f == Format::Markdown ? escape_markdown(s) : escape_latex(s);
}

// \label keys may not hold TeX specials; anything unusual becomes '-'.
std::string label_key(const std::string& s) {
  std::string out;
  for (char c : s) {
    const bool plain = std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ||
                       c == '.' || c == ':';
    out += plain ? c : '-';
  }
  return out;
}

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
  std::array<double, kFitnessColumns.size()> minimum{};
  for (std::size_t c = 0; c < kFitnessColumns.size(); ++c)
    minimum[c] = column_minimum(rows, kFitnessColumns[c].field);
  std::vector<std::vector<std::string>> body;
  for (const auto& r : rows) {
    std::vector<std::string> cells{escape(r.label, f)};
    for (std::size_t c = 0; c < kFitnessColumns.size(); ++c) {
      const double v = r.*kFitnessColumns[c].field;
      const std::string text = format_fitness(v, f);
      cells.push_back(v == minimum[c] ? bold(text, f) : text);
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
  return text + " Fitness statistics over the successful trials; lowest value per column in bold.";
}

}  // namespace

std::string table_markdown(const std::vector<AlgorithmSummary>& rows, const ReportContext& ctx) {
  std::string out = "**Table.** " + caption(ctx, Format::Markdown) + "\n\n";
  const auto header = header_cells(Format::Markdown);
  out += "| " + join(header, " | ") + " |\n|:---";
  for (std::size_t i = 1; i < header.size(); ++i) out += "|---:";
  out += "|\n";
  for (const auto& cells : body_cells(rows, Format::Markdown))
    out += "| " + join(cells, " | ") + " |\n";
  return out;
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
