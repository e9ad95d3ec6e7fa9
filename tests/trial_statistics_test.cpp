#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>

#include "framework/core/error.hpp"
#include "framework/report/results_merge.hpp"
#include "framework/report/stats_tables.hpp"
#include "framework/report/trial_statistics.hpp"
#include "tests/temp_dir.hpp"

namespace hystbench {
namespace {

using test_support::contains;

Experiment experiment(const nlohmann::json& budget) {
  return Experiment::from_json(
      {{"name", "t"},
       {"problem", {{"type", "function"}, {"name", "sphere"}, {"dimension", 2}}},
       {"budget", budget},
       {"trials", 10},
       {"algorithms",
        {{{"name", "de"}, {"label", "A_1"}}, {{"name", "de"}, {"label", "B"}},
         {{"name", "de"}, {"label", "C"}}}}},
      "test");
}

// Trial k of algorithm a reaches `level + k` after 50 evaluations and
// `final + k * 0.001` after 100.
std::vector<TrialResult> trials(int a, double level, double final, int n = 10) {
  std::vector<TrialResult> out;
  for (int k = 0; k < n; ++k) {
    TrialResult r;
    r.algorithm_index = a;
    r.trial = k;
    r.evaluations = 100;
    r.best = final + k * 0.001;
    r.trace = {{1, 1000.0}, {50, level + k}, {100, r.best}};
    r.stop = StopReason::Evaluations;
    out.push_back(r);
  }
  return out;
}

std::vector<std::vector<TrialResult>> campaign() {
  return {trials(0, 10, 1.0), trials(1, 10, 5.0), trials(2, 10, 1.0)};
}

TEST(CampaignStatistics, DefaultReferenceIsTheBestMedianAndMarksFollowHolm) {
  const auto s = campaign_statistics(experiment({{"evaluations", 100}}), campaign(), "", {});
  EXPECT_EQ(s.reference, "A_1");
  EXPECT_FALSE(s.reference_chosen);
  EXPECT_TRUE(s.rows[0].reference);
  EXPECT_TRUE(std::isnan(s.rows[0].p_holm));
  EXPECT_EQ(s.rows[1].mark, '+');  // reference clearly better than B
  EXPECT_LT(s.rows[1].p_holm, 0.05);
  EXPECT_EQ(s.rows[2].mark, '=');  // identical samples
  EXPECT_DOUBLE_EQ(s.rows[2].p_holm, 1.0);
}

TEST(CampaignStatistics, ChosenReferenceSeesTheOthersBetter) {
  const auto s = campaign_statistics(experiment({{"evaluations", 100}}), campaign(), "B", {});
  EXPECT_EQ(s.reference, "B");
  EXPECT_TRUE(s.reference_chosen);
  EXPECT_EQ(s.rows[0].mark, '-');
  EXPECT_EQ(s.rows[2].mark, '-');
}

TEST(CampaignStatistics, UnknownReferenceNamesTheOption) {
  try {
    campaign_statistics(experiment({{"evaluations", 100}}), campaign(), "Z", {});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--reference Z"), std::string::npos) << e.what();
  }
}

TEST(CampaignStatistics, TargetFromBudgetElseNoiseFloor) {
  EXPECT_DOUBLE_EQ(*runtime_target(experiment({{"evaluations", 100}, {"target", 0.5}}), 2.0), 0.5);
  EXPECT_DOUBLE_EQ(*runtime_target(experiment({{"evaluations", 100}}), 2.0), 2.02);
  EXPECT_FALSE(runtime_target(experiment({{"evaluations", 100}}), std::nullopt));
}

TEST(CampaignStatistics, SuccessRateErtAndSnapshots) {
  // Target 1.0055: A and C reach it in trials 0..5 at evaluation 100.
  const auto s = campaign_statistics(experiment({{"evaluations", 100}}), campaign(), "", 1.0055 / 1.01);
  ASSERT_TRUE(s.target);
  EXPECT_EQ(s.rows[0].successes, 6);
  EXPECT_DOUBLE_EQ(s.rows[0].success_rate, 0.6);
  EXPECT_DOUBLE_EQ(s.rows[0].ert, 1000.0 / 6);
  EXPECT_TRUE(std::isinf(s.rows[1].ert));
  // At 10 evaluations every trial is at 1000, at 50 at 10 + k (median 14.5).
  EXPECT_DOUBLE_EQ(s.rows[0].snapshot_medians[0], 1000.0);
  EXPECT_DOUBLE_EQ(s.rows[0].snapshot_medians[1], 14.5);
  EXPECT_NEAR(s.rows[0].snapshot_medians[2], 1.0045, 1e-12);
}

TEST(CampaignStatistics, NoTargetLeavesRuntimeEmptyAndIterationBudgetSnapsAtMostEvaluations) {
  const auto s = campaign_statistics(experiment({{"iterations", 5}}), campaign(), "", {});
  EXPECT_TRUE(std::isnan(s.rows[0].ert));
  // Without an evaluation budget the fractions refer to the 100 evaluations
  // every trial used: 10 % is evaluation 10, still at 1000.
  ASSERT_TRUE(s.budget);
  EXPECT_EQ(*s.budget, 100);
  EXPECT_TRUE(s.budget_from_trials);
  EXPECT_DOUBLE_EQ(s.rows[0].snapshot_medians[0], 1000.0);
  EXPECT_DOUBLE_EQ(s.rows[0].snapshot_medians[1], 14.5);
  ReportContext ctx;
  ctx.experiment = "t";
  const std::string md = stats_markdown(s, ctx), method = stats_method(s);
  EXPECT_NE(method.find("No target fitness is known"), std::string::npos) << method;
  EXPECT_NE(method.find("of 100 evaluations, the most any trial used"), std::string::npos) << method;
  EXPECT_EQ(md.find("Success, ERT"), std::string::npos) << "no target, nothing to say of success: " << md;
  EXPECT_NE(md.find("| B | + |"), std::string::npos) << md;
}

TEST(StatsLatex, BooktabsEscapedLabelsBoldAndCounts) {
  const auto s = campaign_statistics(experiment({{"evaluations", 100}}), campaign(), "", 1.0);
  ReportContext ctx;
  ctx.experiment = "exp_1";
  const std::string tex = stats_latex(s, ctx);
  for (const char* part : {"\\toprule", "\\midrule", "\\bottomrule", "A\\_1 & ref.", "\\textbf{",
                           "\\multicolumn{7}{l}{1/1/0}", "\\label{tab:exp_1-stats}",
                           "at $\\alpha = 0.05$", "reaching 1"})
    EXPECT_NE(tex.find(part), std::string::npos) << part << " missing from:\n" << tex;
  EXPECT_EQ(tex.find("A_1"), std::string::npos) << "unescaped underscore";
  EXPECT_EQ(tex.find("|"), std::string::npos) << "booktabs tables have no vertical rules";
}

// Ten trials each: exact; A against B is complete separation, p = 2 / C(20, 10),
// doubled by Holm over the two comparisons. Eleven trials each: normal.
// A paper's caption: about 40 words at most; the method goes to README.md.
TEST(StatsTables, CaptionIsShortAndTheMethodHoldsTheTests) {
  ReportContext ctx;
  ctx.experiment = "an_experiment";
  ctx.problem = "hammerstein(default.csv)";
  ctx.budget = "20000 evaluations";
  ctx.trials = 30;
  const auto s = campaign_statistics(experiment({{"evaluations", 100}}), campaign(), "", 1.0);
  const std::string md = stats_markdown(s, ctx);
  const std::string caption = md.substr(0, md.find('\n'));
  std::istringstream in(caption);
  std::size_t words = 0;
  for (std::string w; in >> w;) ++words;
  EXPECT_LE(words, 41u) << caption;  // "**Table.**" and 40 words
  for (const char* part : {"rank-sum test against A\\_1", "Holm-corrected", "Success, ERT: reaching 1"})
    EXPECT_TRUE(contains(caption, part)) << part << " missing from: " << caption;
  const std::string method = stats_method(s);
  for (const char* part : {"two-sided Wilcoxon rank-sum test", "(1.01 × noise floor)", "ERT: expected running time"})
    EXPECT_TRUE(contains(method, part)) << part << " missing from: " << method;
}

TEST(StatsTables, MethodSaysWhichRankSumDistributionGaveTheP) {
  ReportContext ctx;
  ctx.experiment = "t";
  const auto ten = campaign_statistics(experiment({{"evaluations", 100}}), campaign(), "", {});
  EXPECT_TRUE(ten.rows[1].p_exact);
  EXPECT_NEAR(ten.rows[1].p_holm / (2 * 2.0 / 184756), 1.0, 1e-12);
  const std::string rule =
      " exact (permutation distribution of the rank sum, ties at their mid-ranks) when both "
      "algorithms have ≤ 10 trials, normal approximation with tie and continuity correction above";
  EXPECT_TRUE(contains(stats_method(ten), rule + " (here exact throughout); Holm-adjusted."));

  const auto eleven = campaign_statistics(experiment({{"evaluations", 100}}),
                                          {trials(0, 10, 1.0, 11), trials(1, 10, 5.0, 11),
                                           trials(2, 10, 1.0, 11)}, "", {});
  EXPECT_FALSE(eleven.rows[1].p_exact);
  EXPECT_TRUE(contains(stats_method(eleven), "above (here normal throughout); Holm"));
}

TEST(StatsMarkdown, AColumnWhoseValuesAllTieHasNoBoldCell) {
  // No trial reaches a negative target: every Success cell is 0/n, ERT infinite.
  const auto s = campaign_statistics(experiment({{"evaluations", 100}}), campaign(), "", -1.0);
  ReportContext ctx;
  ctx.experiment = "t";
  const std::string md = stats_markdown(s, ctx);
  EXPECT_EQ(md.find("**0/"), std::string::npos) << md;
  EXPECT_EQ(md.find("**∞**"), std::string::npos) << md;
}

TEST(FirstDifference, NamesThePathOfTheFirstDifferingField) {
  const nlohmann::json a = {{"budget", {{"evaluations", 400}}}, {"algorithms", {{{"np", 1}}}}};
  nlohmann::json b = a;
  EXPECT_EQ(first_difference(a, b, "experiment"), "");
  b["budget"]["evaluations"] = 500;
  EXPECT_EQ(first_difference(a, b, "experiment"), "experiment.budget.evaluations");
  b = a;
  b["algorithms"][0]["np"] = 2;
  EXPECT_EQ(first_difference(a, b, "experiment"), "experiment.algorithms[0].np");
  b = a;
  b["seed"] = 1;
  EXPECT_EQ(first_difference(a, b, "experiment"), "experiment.seed");
}

}  // namespace
}  // namespace hystbench
