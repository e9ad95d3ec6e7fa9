#include "framework/discovery/candidates_figure.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "framework/io/atomic_file.hpp"
#include "framework/report/gnuplot_script.hpp"

namespace hystbench {
namespace {

// The colours of estimation and held-out data in compare's figures.
constexpr const char* kEstimationColour = "#0072B2";
constexpr const char* kHeldoutColour = "#D55E00";
constexpr double kBarWidth = 0.36;

// The row number $0 moved by `offset`, as a gnuplot expression.
std::string shifted(double offset) {
  if (offset == 0) return "($0)";
  return std::string("($0 ") + (offset < 0 ? "- " : "+ ") + gnuplot::number(std::abs(offset)) + ")";
}

// The bars of one kind of error; `offset` places them in their group.
std::string bars(int column, double offset, const char* colour, const std::string& name,
                 bool tic_labels) {
  return "'diagnosis_candidates.csv' skip 1 using " + shifted(offset) + ":" +
         std::to_string(column) + (tic_labels ? ":xtic(1)" : "") + " with boxes lc rgb '" + colour +
         "' title '" + name + "'";
}

// A mark across each of those bars at the current model's error of the same
// kind, so that a held-out bar is never read against the estimation error.
std::string reference_marks(double offset, const char* colour, const std::string& name,
                            const std::string& current) {
  return "'diagnosis_candidates.csv' skip 1 using " + shifted(offset - kBarWidth / 2) + ":(" +
         current + "):(bar):(0) with vectors nohead lw 3 lc rgb '" + colour +
         "' title 'current, " + name + "'";
}

// The first label, turned 45 degrees, reaches about 0.7 of its length left
// of the first tic: room for it, so that long effect names are not clipped.
int left_margin(const Diagnosis& d) {
  std::size_t longest = 0;
  for (const auto& c : d.candidates) longest = std::max(longest, c.effect.size());
  return std::max(10, int(std::ceil(0.7 * double(longest))));
}

std::string plot_body(const Diagnosis& d, bool heldout, const std::string& unit) {
  std::ostringstream body;
  const double half = heldout ? kBarWidth / 2 + 0.01 : 0.0;
  body << "set datafile separator ','\nset style fill solid 0.45 border\nset boxwidth bar\n"
       << "set xrange [-0.6:" << gnuplot::number(double(d.candidates.size()) - 0.4) << "]\n"
       << "set lmargin " << left_margin(d) << "\n"
       << "set xtics rotate by 45 right nomirror noenhanced\n"
       // Key columns: the bars, their marks, the noise floor.
       << "set key outside top center vertical maxrows " << (heldout ? 2 : 1) << "\n"
       << "set grid ytics\nset logscale y\n"
       << "set ylabel " << gnuplot::quoted("RMSE" + unit) << "\n"
       << "set title " << gnuplot::quoted("RMSE after adding one effect to " + d.model.text())
       << " noenhanced\n"
       << "plot " << bars(2, -half, kEstimationColour, "estimation", true);
  if (heldout) body << ", \\\n     " << bars(3, half, kHeldoutColour, "held out", false);
  body << ", \\\n     "
       << reference_marks(-half, kEstimationColour, "estimation", "current_estimation");
  if (heldout)
    body << ", \\\n     "
         << reference_marks(half, kHeldoutColour, "held out", "current_heldout");
  body << ", \\\n     sigma with lines lw 2 dt 3 lc rgb '#808080' title 'noise floor σ'\n";
  return body.str();
}

}  // namespace

std::filesystem::path write_candidates_figure(const std::filesystem::path& dir, const Diagnosis& d,
                                              const std::string& y_unit) {
  std::ostringstream csv;
  csv << "effect,rmse_after,heldout_rmse_after\n";
  for (const auto& c : d.candidates)
    csv << c.effect << "," << gnuplot::number(c.after.rmse_estimation) << ","
        << gnuplot::number(c.after.rmse_heldout) << "\n";
  write_file_atomic(dir / "diagnosis_candidates.csv", csv.str());
  const double sigma = d.where.noise_floor.sigma;
  const bool heldout = d.errors.n_heldout > 0;
  const std::string unit = y_unit.empty() ? "" : " [" + y_unit + "]";
  const std::string text =
      gnuplot::header("diagnosis_candidates",
                      "RMSE after adding each candidate effect: estimation and held-out\n"
                      "# bars, each marked at the current model's RMSE of the same kind",
                      "diagnosis_candidates.csv") +
      "bar = " + gnuplot::number(kBarWidth) + "  # bar width; a group is two bars\n" +
      "current_estimation = " + gnuplot::number(d.errors.rmse_estimation) +
      "  # current model, estimation RMSE\n" +
      (heldout ? "current_heldout = " + gnuplot::number(d.errors.rmse_heldout) +
                     "  # current model, held-out RMSE\n"
               : "# No held-out data: estimation bars only.\n") +
      "sigma = " + gnuplot::number(sigma) + "  # noise floor estimate\n" +
      (d.candidates.empty()
           ? "# No candidate effect was tried: nothing to draw.\n"
           : gnuplot::render_all_terminals("diagnosis_candidates", plot_body(d, heldout, unit),
                                                    true));
  return gnuplot::write_script(dir, "diagnosis_candidates", text);
}

}  // namespace hystbench
