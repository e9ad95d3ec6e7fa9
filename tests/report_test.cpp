#include <gtest/gtest.h>

#include "tests/temp_dir.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>

#include "framework/report/convergence.hpp"
#include "framework/report/figures.hpp"
#include "framework/report/tables.hpp"
#include "framework/report/figure_style.hpp"
#include "framework/report/gnuplot_script.hpp"
#include "framework/core/error.hpp"

namespace hystbench {
namespace {

using hystbench::test_support::TempDir;

namespace fs = std::filesystem;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

using hystbench::test_support::read;

using hystbench::test_support::contains;

// ---- tables -----------------------------------------------------------------

AlgorithmSummary row(const std::string& label, std::vector<double> fitness, double iterations,
                     double evaluations, long failed, long trials) {
  AlgorithmSummary s;
  s.label = label;
  s.best = s.min = fitness[0];
  s.mean = fitness[1];
  s.max = s.worst = fitness[2];
  s.std = fitness[3];
  s.median = fitness[4];
  s.mean_iterations = iterations;
  s.mean_evaluations = evaluations;
  s.failed = failed;
  s.trials = trials;
  return s;
}

// best/min, mean, max, std, median chosen to exercise every number format.
std::vector<AlgorithmSummary> sample_rows() {
  return {row("de_rand_1", {0.086031, 12.3456, 25000.0, 1.234e-5, 9999.7}, 100, 5000, 0, 10),
          row("jso", {0.5, 1.0, 2.0, 0.3, 1.0}, 99.5, 4999.5, 1, 10),
          row("broken", {kNaN, kNaN, kNaN, kNaN, kNaN}, kNaN, kNaN, 10, 10)};
}

ReportContext sample_context() {
  ReportContext ctx;
  ctx.experiment = "exp_1 100%";
  ctx.problem = "hammerstein";
  ctx.budget = "5000 evaluations";
  ctx.trials = 10;
  ctx.seed = 7;
  ctx.noise_floor = 0.012341;
  ctx.fitness = "SSE";
  return ctx;
}

ReportContext seed_layout() {
  ReportContext ctx = sample_context();
  ctx.seed_table_layout = true;
  return ctx;
}

std::size_t words(const std::string& text) {
  std::istringstream in(text);
  std::size_t n = 0;
  for (std::string w; in >> w;) ++n;
  return n;
}

// The caption line of a Markdown table ("**Table.** ..."), without the mark.
std::string caption_of(const std::string& md) { return md.substr(11, md.find('\n') - 11); }

TEST(TableMarkdown, FormatsNumbersAndBoldsTheLowestPerColumn) {
  const std::string md = table_markdown(sample_rows(), seed_layout());
  EXPECT_TRUE(contains(md, "| Algorithm | Best fitness value | f_avg | f_max | f_min | f_std | "
                           "Median | Iterations | Evaluations | Failed |"));
  // Columns: best, f_avg, f_max, f_min, f_std, median.
  EXPECT_TRUE(contains(md, "| de\\_rand\\_1 | **0.08603** | 12.35 | 2.500e+04 | **0.08603** | "
                           "**1.234e-05** | 1.000e+04 | 100 | 5000 | 0/10 |"))
      << md;
  EXPECT_TRUE(contains(md, "| jso | 0.5000 | **1.000** | **2.000** | 0.5000 | 0.3000 | **1.000** | "
                           "99.5 | 4999.5 | 1/10 |"))
      << md;
  EXPECT_TRUE(contains(md, "| broken | — | — | — | — | — | — | — | — | 10/10 |")) << md;
}

// Best and f_min always agree: the default layout prints one of them, the
// seed's layout both, and its caption says they coincide.
TEST(TableMarkdown, BestBesideFminOnlyInTheSeedsLayout) {
  const std::string md = table_markdown(sample_rows(), sample_context());
  EXPECT_TRUE(contains(md, "| Algorithm | f_avg | f_max | f_min | f_std | Median | Iterations | Evaluations | "
                           "Failed |"))
      << md;
  EXPECT_FALSE(contains(md, "Best fitness value"));
  EXPECT_TRUE(contains(md, "| de\\_rand\\_1 | 12.35 | 2.500e+04 | **0.08603** | **1.234e-05** |")) << md;
  EXPECT_FALSE(contains(caption_of(md), "coincide"));
  EXPECT_TRUE(contains(caption_of(table_markdown(sample_rows(), seed_layout())), "Best and f_min coincide by definition"));
  EXPECT_TRUE(contains(table_latex(sample_rows(), seed_layout()), "Best and $f_{\\min}$ coincide by definition"));
  EXPECT_TRUE(contains(table_method(sample_context()), "table_layout"));
}

TEST(TableMarkdown, CaptionsFitAPaperAndTheMethodGoesToTheReadme) {
  for (const ReportContext& ctx : {sample_context(), seed_layout()}) {
    const std::string caption = caption_of(table_markdown(sample_rows(), ctx));
    EXPECT_LE(words(caption), 40u) << caption;
  }
  EXPECT_TRUE(contains(table_method(sample_context()), "noise floor is the SSE of the true parameters"));
}

TEST(TableMarkdown, ValuesThatPrintAsTheLowestAreAllBold) {
  // 12031.2 and 12034.9 both print as 1.203e+04: a reader cannot tell them
  // apart, so both are bold; 12051 prints as 1.205e+04 and is not.
  const std::string md = table_markdown({row("a", {12034.9, 1, 1, 0, 1}, 1, 1, 0, 1),
                                         row("b", {12031.2, 2, 2, 0, 2}, 1, 1, 0, 1),
                                         row("c", {12051.0, 3, 3, 0, 3}, 1, 1, 0, 1)},
                                        seed_layout());
  EXPECT_TRUE(contains(md, "| a | **1.203e+04** |")) << md;
  EXPECT_TRUE(contains(md, "| b | **1.203e+04** |")) << md;
  EXPECT_TRUE(contains(md, "| c | 1.205e+04 |")) << md;
  EXPECT_TRUE(contains(md, "bold: lowest per column")) << md;
}

TEST(TableMarkdown, CaptionDescribesTheRun) {
  ReportContext ctx = sample_context();
  const std::string md = table_markdown(sample_rows(), ctx);
  const std::string caption = md.substr(0, md.find('\n'));
  for (const char* part : {"exp_1 100%", "hammerstein", "10 trials per algorithm",
                           "budget 5000 evaluations", "seed 7",
                           "Noise floor 0.01234"})
    EXPECT_TRUE(contains(caption, part)) << part << " missing from: " << caption;
  ctx.noise_floor.reset();
  EXPECT_FALSE(contains(table_markdown(sample_rows(), ctx), "Noise floor"));
}

TEST(TableLatex, BooktabsFloatWithEscapedTextAndBoldMath) {
  const std::string tex = table_latex(sample_rows(), seed_layout());
  for (const char* part :
       {"\\begin{table}", "\\centering", "\\caption{", "\\label{tab:exp_1-100-}",
        "\\begin{tabular}{lrrrrrrrrr}", "\\toprule", "\\midrule", "\\bottomrule",
        "\\end{tabular}", "\\end{table}", "exp\\_1 100\\%", "de\\_rand\\_1",
        "\\textbf{0.08603}", "$2.500\\times10^{4}$", "\\textbf{\\boldmath$1.234\\times10^{-5}$}",
        "broken & -- & -- & -- & -- & -- & -- & -- & -- & 10/10 \\\\"})
    EXPECT_TRUE(contains(tex, part)) << part << " missing from:\n" << tex;
  EXPECT_FALSE(contains(tex, "|")) << "booktabs tables have no vertical rules";
  EXPECT_FALSE(contains(tex, "de_rand")) << "unescaped underscore";
}

TEST(TableLatex, EscapesEveryTexSpecialInLabels) {
  const std::string tex =
      table_latex({row("a_b%c&d#e$f{g}", {1, 1, 1, 0, 1}, 1, 1, 0, 1)}, sample_context());
  EXPECT_TRUE(contains(tex, "a\\_b\\%c\\&d\\#e\\$f\\{g\\}")) << tex;
}

TEST(TableCsv, FullPrecisionAndEmptyCellsForMissingValues) {
  auto rows = sample_rows();
  rows[1].label = "jso, tuned";
  rows[1].mean = 0.1;
  const std::string csv = table_csv(rows);
  std::istringstream lines(csv);
  std::string header, de, jso, broken;
  std::getline(lines, header);
  std::getline(lines, de);
  std::getline(lines, jso);
  std::getline(lines, broken);
  EXPECT_EQ(header, "algorithm,best,f_avg,f_max,f_min,f_std,median,iterations,evaluations,failed,"
                    "trials");
  EXPECT_EQ(jso, "\"jso, tuned\",0.5,0.10000000000000001,2,0.5,0.29999999999999999,1,99.5,4999.5,"
                 "1,10");
  EXPECT_EQ(broken, "broken,,,,,,,,,10,10");
  // 17 significant digits read back to the same double.
  std::istringstream fields(de);
  std::string cell;
  std::getline(fields, cell, ',');
  for (double expected : {0.086031, 12.3456, 25000.0, 0.086031, 1.234e-5, 9999.7}) {
    std::getline(fields, cell, ',');
    EXPECT_EQ(std::stod(cell), expected) << cell;
  }
}

TEST(WriteTables, WritesTheThreeFiles) {
  TempDir dir;
  write_tables(dir.path(), sample_rows(), sample_context());
  EXPECT_TRUE(contains(read(dir.path() / "table.md"), "| jso |"));
  EXPECT_TRUE(contains(read(dir.path() / "table.tex"), "\\toprule"));
  EXPECT_TRUE(contains(read(dir.path() / "table.csv"), "broken,,"));
}

// ---- convergence ------------------------------------------------------------

TrialResult trial(std::vector<TracePoint> trace, long evaluations) {
  TrialResult r;
  r.trace = std::move(trace);
  r.evaluations = evaluations;
  r.stop = StopReason::Evaluations;
  r.best = r.trace.empty() ? kInf : r.trace.back().best;
  return r;
}

TrialResult failed_trial() {
  TrialResult r = trial({{1, 0.1}}, 100);
  r.stop = StopReason::Failed;
  return r;
}

long index_of(const ConvergenceCurve& c, long evaluations) {
  for (std::size_t i = 0; i < c.evaluations.size(); ++i)
    if (c.evaluations[i] == evaluations) return long(i);
  ADD_FAILURE() << evaluations << " is not on the grid";
  return 0;
}

void expect_quartiles(const ConvergenceCurve& c, long evaluations, double q25, double median,
                      double q75) {
  const long i = index_of(c, evaluations);
  EXPECT_DOUBLE_EQ(c.q25[i], q25) << "at " << evaluations;
  EXPECT_DOUBLE_EQ(c.median[i], median) << "at " << evaluations;
  EXPECT_DOUBLE_EQ(c.q75[i], q75) << "at " << evaluations;
}

// Trial A improves at 1, 5, 20; trial B at 2, 10; the failed trial is ignored.
std::vector<TrialResult> two_trials() {
  return {trial({{1, 10}, {5, 3}, {20, 1}}, 20), trial({{2, 8}, {10, 2}}, 10), failed_trial()};
}

TEST(ConvergenceCurve, StepFunctionsQuartilesOnTheGrid) {
  const ConvergenceCurve c = convergence_curve("A+B", two_trials(), 200);
  EXPECT_EQ(c.label, "A+B");
  // 200 log-spaced points up to 20 hit every whole number once.
  ASSERT_EQ(c.evaluations.size(), 20u);
  for (long e = 1; e <= 20; ++e) EXPECT_EQ(c.evaluations[e - 1], e);
  expect_quartiles(c, 1, kInf, kInf, kInf);  // B has nothing yet
  expect_quartiles(c, 2, 8.5, 9.0, 9.5);     // {10, 8}
  expect_quartiles(c, 4, 8.5, 9.0, 9.5);     // unchanged until A improves at 5
  expect_quartiles(c, 5, 4.25, 5.5, 6.75);   // {3, 8}
  expect_quartiles(c, 10, 2.25, 2.5, 2.75);  // {3, 2}
  expect_quartiles(c, 19, 2.25, 2.5, 2.75);
  expect_quartiles(c, 20, 1.25, 1.5, 1.75);  // {1, 2}: B keeps its last value
}

TEST(ConvergenceCurve, QuantilesOfATrialStillAtInfinity) {
  auto trials = two_trials();
  trials.push_back(trial({{15, 0.5}}, 20));
  const ConvergenceCurve c = convergence_curve("late", trials, 200);
  expect_quartiles(c, 10, 2.5, 3.0, kInf);  // {2, 3, inf}
  expect_quartiles(c, 20, 0.75, 1.0, 1.5);  // {0.5, 1, 2}
}

TEST(ConvergenceCurve, LogSpacedGridEndsAtTheLastEvaluation) {
  const ConvergenceCurve c = convergence_curve("x", {trial({{1, 5}, {4000, 1}}, 5000)}, 20);
  ASSERT_GE(c.evaluations.size(), 15u);
  EXPECT_LE(c.evaluations.size(), 20u);
  EXPECT_EQ(c.evaluations.front(), 1);
  EXPECT_EQ(c.evaluations.back(), 5000);
  for (std::size_t i = 1; i < c.evaluations.size(); ++i)
    EXPECT_LT(c.evaluations[i - 1], c.evaluations[i]);
  // Log spacing: the middle point sits near sqrt(5000), not near 2500.
  EXPECT_NEAR(double(c.evaluations[c.evaluations.size() / 2]), 70.0, 40.0);
  EXPECT_EQ(c.median.back(), 1.0);
}

TEST(ConvergenceCurve, OnlyFailedTrialsGiveAnEmptyCurve) {
  const ConvergenceCurve c = convergence_curve("x", {failed_trial()});
  EXPECT_TRUE(c.evaluations.empty());
  EXPECT_TRUE(c.median.empty());
}

TEST(ConvergenceCsv, LongFormatWithInfinity) {
  TempDir dir;
  const auto curve = convergence_curve("A,B", two_trials(), 200);
  write_convergence_csv(dir.path() / "convergence.csv",
                        {curve, convergence_curve("C", two_trials(), 3)});
  const std::string csv = read(dir.path() / "convergence.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "label,evaluations,q25,median,q75");
  EXPECT_TRUE(contains(csv, "\n\"A,B\",1,inf,inf,inf\n")) << csv;
  EXPECT_TRUE(contains(csv, "\n\"A,B\",2,8.5,9,9.5\n")) << csv;
  EXPECT_TRUE(contains(csv, "\n\"A,B\",5,4.25,5.5,6.75\n")) << csv;
  EXPECT_TRUE(contains(csv, "\nC,20,1.25,1.5,1.75\n")) << csv;
}

// ---- figures ----------------------------------------------------------------

// The axis names the fitness only when the problem says what it is: a test
// function's or a controller's fitness is not a sum of squares.
TEST(ConvergenceFigure, AxisNamesTheProblemsFitness) {
  TempDir dir;
  ReportContext ctx = sample_context();
  ctx.fitness = "";
  const std::vector<ConvergenceCurve> curves{convergence_curve("de_1", two_trials(), 200)};
  std::string gp = read(write_convergence_figure(dir.path(), curves, ctx));
  EXPECT_TRUE(contains(gp, "set ylabel \"Best-so-far fitness\"\n")) << gp;
  ctx.fitness = "error ratio";
  gp = read(write_convergence_figure(dir.path(), curves, ctx));
  EXPECT_TRUE(contains(gp, "set ylabel \"Best-so-far fitness (error ratio)\"")) << gp;
}

TEST(ConvergenceFigure, ScriptDrawsMedianAndBandFromFiniteRows) {
  TempDir dir;
  std::vector<ConvergenceCurve> curves{convergence_curve("de_1", two_trials(), 200),
                                       convergence_curve("dead", {failed_trial()})};
  const fs::path script = write_convergence_figure(dir.path(), curves, sample_context());
  EXPECT_EQ(script, dir.path() / "convergence.gp");
  const std::string gp = read(script);
  for (const char* part :
       {"set logscale xy", "Best-so-far fitness (SSE)", "Function evaluations",
        "Convergence — exp_1 100% (hammerstein)", "interquartile range over 10 trials",
        "transparent solid 0.25", "with filledcurves", "title \"de_1\" noenhanced",
        "set terminal svg size 900,560 font \"Helvetica,12\"",
        "set terminal pngcairo size 900,560 font \"Helvetica,11\"",
        "set terminal pdfcairo size 6in,3.75in font \"Helvetica,10\"", "unset output",
        "noise_floor = 0.012341", "gnuplot convergence.gp"})
    EXPECT_TRUE(contains(gp, part)) << part << " missing from:\n" << gp;
  EXPECT_FALSE(contains(gp, "dead")) << "a curve without a finite value has nothing to draw";
  const std::string dat = read(dir.path() / "convergence.dat");
  // Evaluation 1 (median +inf) is left out; the band block follows the line block.
  EXPECT_TRUE(contains(dat, "# evaluations q25 median q75\n2 8.5 9 9.5\n")) << dat;
  EXPECT_TRUE(contains(dat, "\n\n\n# index 1: de_1 (quartile band)")) << dat;
  EXPECT_FALSE(contains(dat, "inf"));
}

// The whole trace shows: the axis ends above the highest upper quartile,
// 9.5 here (of 10 and 8 at evaluation 2), not 3x a median after 1 % of the budget.
TEST(ConvergenceFigure, AxisShowsTheWholeTrace) {
  TempDir dir;
  const std::vector<ConvergenceCurve> curves{convergence_curve("de_1", two_trials(), 200)};
  const std::string gp = read(write_convergence_figure(dir.path(), curves, sample_context()));
  EXPECT_TRUE(contains(gp, "set yrange [*:14.25]")) << gp;
  EXPECT_FALSE(contains(gp, "start above the axis")) << gp;
}

// First values astronomically above the rest (a model that diverges at its
// first candidates) would flatten every curve: the axis stops lower and a
// label says how high the traces start.
TEST(ConvergenceFigure, AstronomicalStartsAreClippedAndSaidSo) {
  TempDir dir;
  const std::vector<ConvergenceCurve> curves{convergence_curve(
      "de_1", {trial({{1, 1e30}, {5, 3}, {1000, 1}}, 1000), trial({{1, 1e30}, {6, 2}, {1000, 1}}, 1000)}, 200)};
  const std::string gp = read(write_convergence_figure(dir.path(), curves, sample_context()));
  EXPECT_TRUE(contains(gp, "traces start above the axis, up to 1e+30")) << gp;
  EXPECT_TRUE(contains(gp, "set yrange [*:7.5]")) << gp;  // 3x the median 2.5 after evaluation 10
}

// The legend goes above the plot area, outside the data.
TEST(ConvergenceFigure, LegendSitsAboveThePlot) {
  TempDir dir;
  const std::vector<ConvergenceCurve> curves{convergence_curve("de_1", two_trials(), 200)};
  const std::string gp = read(write_convergence_figure(dir.path(), curves, sample_context()));
  EXPECT_TRUE(contains(gp, "set key outside top center horizontal")) << gp;
}

// --figure-style paper: no title anywhere, journal widths, 8 pt text.
TEST(FigureStyle, PaperDropsTitlesAndUsesColumnWidths) {
  struct Restore {
    ~Restore() { gnuplot::set_figure_style(gnuplot::FigureStyle::Screen); }
  } restore;
  gnuplot::set_figure_style(gnuplot::FigureStyle::Paper);
  const std::string single = gnuplot::render_all_terminals("f", "  set title \"T\"\n  plot x\n");
  for (const char* part : {"pdfcairo size 8.5cm,6cm font \"Helvetica,8\"", "pngcairo size 1004,709",
                           "  unset title\n  plot x"})
    EXPECT_TRUE(contains(single, part)) << part << " missing from:\n" << single;
  EXPECT_FALSE(contains(single, "  set title"));
  EXPECT_TRUE(contains(gnuplot::render_all_terminals("f", "plot x\n", true), "pdfcairo size 17.5cm,12cm"));
  const std::string stacked = gnuplot::render_all_terminals(
      "f", "  set multiplot layout 2, 1 title \"A \\\"b\\\"\" noenhanced\n  plot x\n", true);
  EXPECT_TRUE(contains(stacked, "  set multiplot layout 2, 1\n")) << stacked;
  TempDir dir;
  const std::vector<ConvergenceCurve> curves{convergence_curve("de_1", two_trials(), 200)};
  const std::string gp = read(write_convergence_figure(dir.path(), curves, sample_context()));
  EXPECT_TRUE(contains(gp, "  unset title\n")) << gp;
  EXPECT_THROW(gnuplot::parse_figure_style("journal", "--figure-style"), InputError);
}

struct FitData {
  Eigen::VectorXd t, u, y, yhat;
  std::vector<std::string> segments;
};

// Six samples: segment "a", then "b", then "a" again.
FitData fit_data() {
  FitData d;
  d.t = Eigen::VectorXd::LinSpaced(6, 0.0, 0.5);
  d.u = (Eigen::VectorXd(6) << 0, 1, 0, -1, 0, 1).finished();
  d.y = (Eigen::VectorXd(6) << 0.1, 1.2, 0.3, -0.4, 0.5, 1.25).finished();
  d.yhat = (Eigen::VectorXd(6) << 0.0, 1.0, 0.25, -0.5, 0.5, 1.0).finished();
  d.segments = {"a", "a", "b", "b", "a", "a"};
  return d;
}

TEST(FitFigures, WritesDataAndBothScripts) {
  TempDir dir;
  const FitData d = fit_data();
  const auto scripts = write_fit_figures(dir.path(), "DE/rand 1", d.t, d.u, d.y, d.yhat,
                                         d.segments, sample_context());
  ASSERT_EQ(scripts.size(), 2u);
  EXPECT_EQ(scripts[0], dir.path() / "fit_DE_rand_1_time.gp");
  EXPECT_EQ(scripts[1], dir.path() / "fit_DE_rand_1_loops.gp");
  const std::string csv = read(dir.path() / "fit_DE_rand_1.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "t,u,y_measured,y_model,residual,segment");
  EXPECT_TRUE(contains(csv, "\n0.10000000000000001,1,1.2,1,0.19999999999999996,a\n")) << csv;

  const std::string loops = read(dir.path() / "fit_DE_rand_1_loops.dat");
  // Segment "a" is one block whose two runs are broken by a single blank line.
  EXPECT_TRUE(contains(loops, "1 1.2 1\n\n0 0.5 0.5\n")) << loops;
  EXPECT_TRUE(contains(loops, "\n\n\n# index 1: b\n")) << loops;

  const std::string time = read(scripts[0]);
  for (const char* part : {"Time t [s]", "Output y", "y − ŷ", "set multiplot", "DE/rand 1",
                           "fit_DE_rand_1.csv", "set label \"b\"", "set arrow from 0.2,"})
    EXPECT_TRUE(contains(time, part)) << part << " missing from:\n" << time;
  const std::string loop_gp = read(scripts[1]);
  for (const char* part : {"Input u", "Output y", "array segment[2] = [\"a\", \"b\"]",
                           "set multiplot layout rows, cols", "fit_DE_rand_1_loops.dat",
                           "index i-1", "unset output"})
    EXPECT_TRUE(contains(loop_gp, part)) << part << " missing from:\n" << loop_gp;
}

// A good model must not hide the measurement: the measurement is plotted
// first as a broad light line, the model thin over it, in both figures.
TEST(FitFigures, MeasurementIsABroadBandUnderAThinModelLine) {
  TempDir dir;
  const FitData d = fit_data();
  for (const auto& script : write_fit_figures(dir.path(), "de", d.t, d.u, d.y, d.yhat,
                                              d.segments, sample_context())) {
    const std::string gp = read(script);
    const auto measured = gp.find("with lines lw 4 lc rgb \"#b4b4b4\" title \"measured\"");
    const auto model = gp.find("with lines lw 1 lc rgb \"#0072B2\" title \"model\"");
    ASSERT_NE(measured, std::string::npos) << gp;
    ASSERT_NE(model, std::string::npos) << gp;
    EXPECT_LT(measured, model) << "the model is drawn over the measurement";
  }
}

TEST(FitFigures, WithoutSegmentsOnePanelAndNoSegmentColumn) {
  TempDir dir;
  const FitData d = fit_data();
  const auto scripts =
      write_fit_figures(dir.path(), "pso", d.t, d.u, d.y, d.yhat, {}, sample_context());
  EXPECT_EQ(read(dir.path() / "fit_pso.csv").substr(0, 32), "t,u,y_measured,y_model,residual\n");
  EXPECT_TRUE(contains(read(scripts[1]), "panels = 1\n"));
  EXPECT_FALSE(contains(read(scripts[0]), "set arrow from"));
}

TEST(FitFigures, RejectsMismatchedLengths) {
  TempDir dir;
  FitData d = fit_data();
  d.segments.pop_back();
  EXPECT_THROW(write_fit_figures(dir.path(), "x", d.t, d.u, d.y, d.yhat, d.segments, {}),
               std::invalid_argument);
}

// The first data line of a binned time plot: t, then min and max of y and model.
std::array<double, 5> first_bin(const std::filesystem::path& dat) {
  std::ifstream in(dat);
  std::string header;
  std::getline(in, header);
  std::array<double, 5> v{};
  for (double& x : v) in >> x;
  return v;
}

// A long record is drawn as the range of each curve per bin of samples: a
// fast segment shows as its envelope, not as a block of ink.
TEST(FitFigures, LongRecordsAreDrawnAsEnvelopesPerBin) {
  TempDir dir;
  const Eigen::Index n = 6000;
  const Eigen::VectorXd t = Eigen::VectorXd::LinSpaced(n, 0.0, 5.999);
  Eigen::VectorXd y(n);
  for (Eigen::Index i = 0; i < n; ++i) y[i] = std::sin(2 * M_PI * 50 * t[i]);
  const Eigen::VectorXd yhat = 0.9 * y;
  const auto scripts = write_fit_figures(dir.path(), "de", t, y, y, yhat, {}, sample_context());
  const std::string gp = read(scripts[0]);
  EXPECT_TRUE(contains(gp, "fit_de_time.dat")) << gp;
  EXPECT_TRUE(contains(gp, "with filledcurves")) << gp;
  const std::string dat = read(dir.path() / "fit_de_time.dat");
  EXPECT_EQ(dat.substr(0, dat.find('\n')), "# t y_min y_max model_min model_max residual_min residual_max");
  EXPECT_EQ(std::count(dat.begin(), dat.end(), '\n'), 401);
  // A bin holds 15 samples, three quarters of a period: the sine turns three
  // times in bins 0 and 1, so bin 0 spans both, the whole swing, and its
  // edge does not zigzag with the bins that miss a peak.
  const auto fast = first_bin(dir.path() / "fit_de_time.dat");
  EXPECT_NEAR(fast[1], y.head(30).minCoeff(), 1e-9);
  EXPECT_NEAR(fast[2], y.head(30).maxCoeff(), 1e-9);
  EXPECT_NEAR(fast[4], 0.9 * fast[2], 1e-9);
  // A slow sine keeps each bin's own range: its edges trace the curve.
  for (Eigen::Index i = 0; i < n; ++i) y[i] = std::sin(2 * M_PI * 0.5 * t[i]);
  write_fit_figures(dir.path(), "slow", t, y, y, 0.9 * y, {}, sample_context());
  const auto slow = first_bin(dir.path() / "fit_slow_time.dat");
  EXPECT_NEAR(slow[1], y.head(15).minCoeff(), 1e-9);
  EXPECT_NEAR(slow[2], y.head(15).maxCoeff(), 1e-9);
  // A short record keeps every sample.
  const FitData d = fit_data();
  EXPECT_TRUE(contains(read(write_fit_figures(dir.path(), "short", d.t, d.u, d.y, d.yhat, d.segments,
                                              sample_context())[0]), "fit_short.csv"));
}

bool have_gnuplot() { return std::system("command -v gnuplot > /dev/null 2>&1") == 0; }

TEST(RenderFigures, WritesSvgPngAndPdfForEveryScript) {
  if (!have_gnuplot()) GTEST_SKIP() << "gnuplot is not installed";
  TempDir dir;
  const FitData d = fit_data();
  std::vector<fs::path> scripts{write_convergence_figure(
      dir.path(), {convergence_curve("a", two_trials())}, sample_context())};
  for (const auto& s :
       write_fit_figures(dir.path(), "a", d.t, d.u, d.y, d.yhat, d.segments, sample_context()))
    scripts.push_back(s);
  std::string note = "stale";
  const auto images = render_figures(dir.path(), scripts, note);
  EXPECT_EQ(note, "");
  ASSERT_EQ(images.size(), 9u);
  for (const auto& image : images) EXPECT_GT(fs::file_size(image), 1000u) << image;
  EXPECT_EQ(images[1], dir.path() / "convergence.png");
}

TEST(RenderFigures, ReportsTheFirstGnuplotError) {
  if (!have_gnuplot()) GTEST_SKIP() << "gnuplot is not installed";
  TempDir dir;
  std::ofstream(dir.path() / "bad.gp") << "set output 'bad.svg'\nplot no_such_function(x)\n";
  std::string note;
  const auto images = render_figures(dir.path(), {dir.path() / "bad.gp"}, note);
  EXPECT_TRUE(contains(note, "gnuplot failed on bad.gp")) << note;
  EXPECT_TRUE(contains(note, "no_such_function") || contains(note, "undefined")) << note;
  EXPECT_TRUE(images.empty());
}

TEST(RenderFigures, WithoutGnuplotSaysHowToRenderLater) {
  TempDir dir;
  const char* old = std::getenv("PATH");
  const std::string saved = old ? old : "";
  ::setenv("PATH", dir.path().c_str(), 1);  // an empty folder: no gnuplot anywhere
  std::string note;
  const auto images = render_figures(dir.path(), {dir.path() / "convergence.gp"}, note);
  ::setenv("PATH", saved.c_str(), 1);
  EXPECT_TRUE(images.empty());
  EXPECT_TRUE(contains(note, "gnuplot not found")) << note;
  EXPECT_TRUE(contains(note, "apt-get install gnuplot-nox")) << note;
  EXPECT_TRUE(contains(note, dir.path().string())) << note;
}

}  // namespace
}  // namespace hystbench
