#include "framework/report/ranking_figure.hpp"

#include <algorithm>
#include <numeric>

#include "framework/io/atomic_file.hpp"
#include "framework/report/gnuplot_script.hpp"
#include "framework/report/table_format.hpp"

namespace hystbench {
namespace {

// Algorithm indices from the best average rank to the worst.
std::vector<int> by_rank(const FriedmanRanking& r) {
  std::vector<int> order(r.labels.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return r.test.average_ranks[a] < r.test.average_ranks[b];
  });
  return order;
}

// From rank 1 to k, widened so that no CD bar is cut off at either end.
std::string x_range(const FriedmanRanking& r) {
  const auto& avg = r.test.average_ranks;
  const double half = r.critical_difference.value_or(0.0) / 2;
  const double lo = std::min(0.5, *std::min_element(avg.begin(), avg.end()) - half - 0.2);
  const double hi = std::max(avg.size() + 0.5, *std::max_element(avg.begin(), avg.end()) + half + 0.2);
  return "set xrange [" + gnuplot::number(lo) + ":" + gnuplot::number(hi) + "]\n";
}

std::string settings(const FriedmanRanking& r, const std::vector<int>& order) {
  const std::string k = std::to_string(r.labels.size());
  std::string tics;
  for (std::size_t i = 0; i < order.size(); ++i)
    tics += (i ? ", " : "") + gnuplot::quoted(r.labels[order[i]]) + " " + std::to_string(i + 1);
  const std::string bars =
      r.critical_difference
          ? "bars: average rank ± CD/2, CD = " +
                table::format_fitness(*r.critical_difference, table::Format::Markdown) +
                " (Nemenyi, α = 0.05); bars that do not overlap differ"
          : "no Nemenyi CD beyond 10 algorithms";
  return "set title " + gnuplot::quoted("Friedman average ranks over " +
                                        std::to_string(r.blocks.size()) + " data sets") +
         ".\"\\n\"." + gnuplot::quoted(bars) + " noenhanced\n" +
         "set xlabel \"Average rank (1 = best)\"\n" + x_range(r) + "set xtics 1, 1, " + k + "\n" +
         "set yrange [" + k + ".5:0.5]\nset ytics (" + tics + ") noenhanced\n" +
         "set grid xtics lt 1 lc rgb \"#e0e0e0\" lw 1\nunset key\n";
}

std::string plot(const FriedmanRanking& r) {
  const std::string half = gnuplot::number(r.critical_difference.value_or(0.0) / 2);
  const std::string style = " pointtype 7 pointsize 1.2 linewidth 2 lc rgb \"#1f77b4\"\n";
  if (!r.critical_difference) return "  plot \"ranks.dat\" using 2:1 with points" + style;
  return "  plot \"ranks.dat\" using 2:1:($2-" + half + "):($2+" + half + ") with xerrorbars" +
         style;
}

}  // namespace

std::filesystem::path write_ranking_figure(const std::filesystem::path& dir,
                                           const FriedmanRanking& r) {
  const auto order = by_rank(r);
  std::string dat = "# position average_rank label\n";
  for (std::size_t i = 0; i < order.size(); ++i)
    dat += std::to_string(i + 1) + " " + gnuplot::number(r.test.average_ranks[order[i]]) + " " +
           gnuplot::quoted(r.labels[order[i]]) + "\n";
  write_file_atomic(dir / "ranks.dat", dat);
  const std::string text =
      gnuplot::header("ranks", "Friedman average rank of each algorithm over the data sets,\n# "
                               "with Nemenyi critical-difference bars",
                      "ranks.dat (position average_rank label, best first)") +
      settings(r, order) + gnuplot::render_all_terminals("ranks", plot(r));
  return gnuplot::write_script(dir, "ranks", text);
}

}  // namespace hystbench
