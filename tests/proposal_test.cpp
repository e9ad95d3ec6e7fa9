// Proposing a missing term: orthogonal forward regression on known columns,
// the term library, the generated effect's source, the partial-help share,
// and `propose` on actuators with planted physics the catalog lacks
// (tests/planted_physics.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "framework/core/error.hpp"
#include "framework/discovery/beyond_catalog.hpp"
#include "framework/discovery/effect_source.hpp"
#include "framework/discovery/model_fit.hpp"
#include "framework/discovery/proposal.hpp"
#include "framework/model/holdout.hpp"
#include "framework/stats/forward_regression.hpp"
#include "tests/planted_physics.hpp"

namespace hystbench {
namespace {

Eigen::MatrixXd random_columns(Eigen::Index n, Eigen::Index m, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> z;
  Eigen::MatrixXd P(n, m);
  for (Eigen::Index j = 0; j < m; ++j)
    for (Eigen::Index i = 0; i < n; ++i) P(i, j) = z(rng);
  return P;
}

TEST(ForwardRegression, FindsTheTwoColumnsOfTheTargetAndTheirCoefficients) {
  const Eigen::MatrixXd P = random_columns(2000, 30, 1);
  const Eigen::VectorXd noise = 0.01 * random_columns(2000, 1, 2);
  const Eigen::VectorXd e = 2.0 * P.col(7) - 0.5 * P.col(19) + noise;
  const ForwardRegression r = forward_regression({P, e, {}});
  ASSERT_EQ(r.steps.size(), 2u);
  EXPECT_EQ(r.steps[0].column, 7);
  EXPECT_EQ(r.steps[1].column, 19);
  EXPECT_NEAR(r.coefficients[0], 2.0, 1e-3);
  EXPECT_NEAR(r.coefficients[1], -0.5, 1e-3);
  EXPECT_GT(r.explained, 0.9999);
  EXPECT_EQ(r.refused_by, "bic");
}

TEST(ForwardRegression, CreditsACorrelatedCandidateOnlyWithWhatTheChosenOneLeaves) {
  Eigen::MatrixXd P = random_columns(2000, 3, 3);
  P.col(1) = P.col(0) + 0.01 * P.col(2);  // nearly the true column
  const Eigen::VectorXd e = P.col(0);
  const ForwardRegression r = forward_regression({P, e, {}});
  ASSERT_EQ(r.steps.size(), 1u);
  EXPECT_EQ(r.steps[0].column, 0);
  EXPECT_EQ(r.steps[0].runner_up, 1);  // as good as the term on its own ...
  EXPECT_GT(r.steps[0].runner_up_err, 0.99);
  EXPECT_NEAR(r.first_err[1], r.steps[0].runner_up_err, 1e-12);
}

TEST(ForwardRegression, FixedColumnsComeFirstAndAreNeverCredited) {
  const Eigen::MatrixXd P = random_columns(1000, 5, 4);
  const Eigen::MatrixXd fixed = P.col(2);
  const Eigen::VectorXd e = 3.0 * P.col(2) + P.col(4);
  const ForwardRegression r = forward_regression({P, e, fixed});
  ASSERT_EQ(r.steps.size(), 1u);
  EXPECT_EQ(r.steps[0].column, 4);
  EXPECT_NEAR(r.coefficients[0], 1.0, 1e-9);
  EXPECT_NEAR(r.fixed_coefficients[0], 3.0, 1e-9);
  EXPECT_NEAR(r.fixed_share, 0.9, 0.05);
}

TEST(ForwardRegression, HeldOutRowsRefuseAColumnThatOnlyFitsTheEstimationNoise) {
  Eigen::MatrixXd P = random_columns(400, 2, 5);
  Eigen::VectorXd e = P.col(0);
  e.head(200) += 0.3 * P.col(1).head(200);  // column 1 matters on the fit rows only
  const RegressionRows fit{P.topRows(200), e.head(200), {}}, check{P.bottomRows(200), e.tail(200), {}};
  const ForwardRegression r = forward_regression(fit, {}, &check);
  ASSERT_EQ(r.steps.size(), 1u);
  EXPECT_EQ(r.steps[0].column, 0);
  EXPECT_EQ(r.refused_by, "heldout");
  EXPECT_EQ(r.refused.column, 1);
}

TEST(TermLibrary, HoldsBothParitiesOfEveryPowerAtEveryStage) {
  const auto library = term_library(3);
  EXPECT_EQ(library.size(), 96u);
  EXPECT_EQ(term_library(6).size(), 336u);
  int cubes = 0;
  for (const auto& t : library)
    if (t.stage == TermStage::Dynamics && t.rate.power == 0 && t.signal.power == 3) {
      ++cubes;
      EXPECT_TRUE(t.text() == "x³" || t.text() == "|x|³");
    }
  EXPECT_EQ(cubes, 2);
  const CandidateTerm odd_square{TermStage::Static, {2, true}, {1, false}};
  EXPECT_EQ(odd_square.text(), "v·|v|·|v'|");
  EXPECT_DOUBLE_EQ(odd_square.value(-2.0, -3.0), -12.0);
  EXPECT_DOUBLE_EQ((CandidateTerm{TermStage::Output, {3, false}, {}}.value(-2.0, 0.0)), 8.0);
  EXPECT_EQ(rate_of(Eigen::Vector3d(1.0, 3.0, 2.0), 0.5), Eigen::Vector3d(0.0, 4.0, -2.0));  // none before the record
}

TEST(EffectSource, NamesTheTermAndRefusesAForceWithoutMsd) {
  ProposedTerm t;
  t.term = {TermStage::Static, {1, true}, {1, false}};
  t.coefficient = 0.002;
  const std::string source = proposed_effect_source(t, {"rate_gain", "data.csv", "hysteresis,msd"});
  EXPECT_NE(source.find("HYSTBENCH_EFFECT(RateGain)"), std::string::npos);
  EXPECT_NE(source.find("EffectStage::Nonlinearity"), std::string::npos);
  EXPECT_NE(source.find("-0.02, 0.02, 0"), std::string::npos);  // c within ten times the proposal
  EXPECT_NE(source.find("proposed from data"), std::string::npos);
  t.term.stage = TermStage::Dynamics;
  EXPECT_NE(proposed_effect_source(t, {"stiff", "data.csv", "msd"}).find("i.extends = \"msd\""),
            std::string::npos);
  EXPECT_THROW(proposed_effect_source(t, {"stiff", "data.csv", "hysteresis,arx"}), InputError);
  EXPECT_THROW(check_effect_name("msd"), InputError);
  EXPECT_THROW(check_effect_name("Bad-Name"), InputError);
}

TEST(BeyondCatalog, ExcessShareIsWhatACandidateRemovesAboveTheNoise) {
  EXPECT_DOUBLE_EQ(excess_share(5.0, 3.0, 0.0), 16.0 / 25.0);
  EXPECT_DOUBLE_EQ(excess_share(5.0, 4.0, 3.0), 9.0 / 16.0);
  EXPECT_TRUE(std::isnan(excess_share(1.0, 0.9, 1.0)));
}

struct PlantedFit {
  Model model;
  Eigen::VectorXd x;
  ModelData data;
};

PlantedFit fit_planted(const planted::System& s, const std::string& start, Eigen::Index n = 6000) {
  const double ts = 1e-3;
  const Measurement m = planted::simulate(s, planted::multisine(n, ts), ts);
  PlantedFit f{Model::parse(start), {}, ModelData(m, SignalScales::of(m))};
  apply_holdout(f.data, HoldoutSpec{});
  FitOptions o;
  o.restarts = 2;
  f.x = fit_model(f.model, f.data, o).x;
  return f;
}

TEST(Proposal, PlantedRateDependentGainIsProposedAtTheStaticBlockAndNothingElse) {
  planted::System s;
  s.rate_gain = 0.001;
  const PlantedFit f = fit_planted(s, "msd");
  const Proposal p = propose_terms(f.model, f.x, f.data);
  ASSERT_EQ(p.terms.size(), 1u);
  EXPECT_EQ(p.terms[0].term.text(), "v·|v'|");
  EXPECT_EQ(p.terms[0].term.stage, TermStage::Static);
  EXPECT_GT(p.terms[0].err, 0.9);
  // The same term at the input is one column here (only the gain between): the static block is said.
  EXPECT_EQ(p.terms[0].runner_up, "input: u·|u'|");
  EXPECT_LT(p.rmse_heldout_after, 1.2 * s.noise);
  EXPECT_GT(p.rmse_heldout, 5.0 * s.noise);
}

TEST(Proposal, PlantedCubicStiffnessIsProposedInsideTheDynamics) {
  planted::System s;
  s.cubic = 0.01;
  const PlantedFit f = fit_planted(s, "msd");
  const Proposal p = propose_terms(f.model, f.x, f.data);
  ASSERT_FALSE(p.terms.empty());
  EXPECT_EQ(p.terms[0].term.text(), "x³");
  EXPECT_EQ(p.terms[0].term.stage, TermStage::Dynamics);
  EXPECT_LT(p.terms[0].coefficient, 0.0);  // a hardening spring: a restoring force
  EXPECT_LT(p.rmse_heldout_after, 1.2 * s.noise);
}

TEST(Proposal, NothingIsProposedWhenTheModelIsRight) {
  planted::System s;  // no planted term: msd is the truth
  const PlantedFit f = fit_planted(s, "msd");
  const Proposal p = propose_terms(f.model, f.x, f.data);
  EXPECT_TRUE(p.terms.empty()) << p.terms[0].term.text();
}

}  // namespace
}  // namespace hystbench
