// Proposing a missing term: orthogonal forward regression on known columns,
// the term library, the generated effect's source, the partial-help share,
// and `propose` on actuators with planted physics the catalog lacks
// (tests/planted_physics.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "framework/core/error.hpp"
#include "framework/discovery/beyond_catalog.hpp"
#include "framework/discovery/diagnosis.hpp"
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

// Column 1 explains more of the fit rows than column 0 but holds only
// there: ranked by held-out gain, column 0 comes first and column 1 is then
// refused. A fixed column checks that the check rows lose their part along
// it as the fit rows do.
TEST(ForwardRegression, HeldOutRowsRankAColumnThatHoldsOnThemAboveOneThatOnlyFitsTheEstimationRows) {
  const Eigen::MatrixXd P = random_columns(800, 4, 6);
  const Eigen::MatrixXd fixed = P.col(3);
  Eigen::VectorXd e = 3.0 * P.col(3) + 0.5 * P.col(0) + 0.01 * P.col(2);
  e.head(400) += 0.8 * P.col(1).head(400);
  const RegressionRows fit{P.topRows(400), e.head(400), fixed.topRows(400)},
      check{P.bottomRows(400), e.tail(400), fixed.bottomRows(400)};
  const ForwardRegression by_err = forward_regression(fit);
  ASSERT_FALSE(by_err.steps.empty());
  EXPECT_EQ(by_err.steps[0].column, 1);  // the larger share of the fit rows
  const ForwardRegression r = forward_regression(fit, {}, &check);
  ASSERT_EQ(r.steps.size(), 1u);
  EXPECT_EQ(r.steps[0].column, 0);
  EXPECT_EQ(r.steps[0].runner_up, 1);
  EXPECT_LT(r.steps[0].check_rms, 0.5 * r.check_rms);
  EXPECT_EQ(r.refused_by, "heldout");
  EXPECT_EQ(r.refused.column, 1);
  EXPECT_NEAR(r.fixed_coefficients[0], 3.0, 0.1);
}

// The library's term of that text; a failure (and a stand-in term) when there is none.
CandidateTerm library_term(const std::vector<CandidateTerm>& library, const std::string& text) {
  const auto t = std::find_if(library.begin(), library.end(), [&](const CandidateTerm& c) { return c.text() == text; });
  if (t != library.end()) return *t;
  ADD_FAILURE() << "no term " << text << " in the library";
  return {};
}

TEST(TermLibrary, HoldsBothParitiesOfEveryPowerAtEveryStage) {
  const auto library = term_library(3);
  // 24 terms of one signal and its rate for each of u, v, w, x, y; both
  // parities of the square root of u, v, x and y; 3 play operators; 6 pairs
  // of signals × 4 signal-or-rate choices × 4 parities.
  EXPECT_EQ(library.size(), 5u * 24u + 8u + 3u + 96u);
  EXPECT_EQ(term_library(6).size(), 5u * 84u + 8u + 3u + 96u);
  EXPECT_EQ(term_library(1).size(), 5u * 4u + 8u + 3u);  // no products below degree 2
  int cubes = 0;
  for (const auto& t : library)
    if (t.stage == TermStage::Dynamics && t.factors.size() == 1 && !t.factors[0].rate && t.factors[0].power == 3) {
      ++cubes;
      EXPECT_TRUE(t.text() == "x³" || t.text() == "|x|³");
      EXPECT_TRUE(t.of_one_signal());
    }
  EXPECT_EQ(cubes, 2);
  const CandidateTerm odd_square{TermStage::Static, {{TermSignal::Drive, false, 2, true}, {TermSignal::Drive, true, 1, false}}};
  EXPECT_EQ(odd_square.text(), "v·|v|·|v'|");
  EXPECT_EQ(odd_square.degree(), 3);
  EXPECT_DOUBLE_EQ(odd_square.factors[0].value(-2.0) * odd_square.factors[1].value(-3.0), -12.0);
  EXPECT_DOUBLE_EQ((TermFactor{TermSignal::Output, false, 3, false}.value(-2.0)), 8.0);
  const CandidateTerm root = library_term(library, "sign(y)·√|y|");
  EXPECT_EQ(root.stage, TermStage::Output);
  EXPECT_TRUE(root.has_root() && root.of_one_signal());
  EXPECT_EQ(root.degree(), 1);
  EXPECT_DOUBLE_EQ(root.factors[0].value(-4.0), -2.0);
  EXPECT_DOUBLE_EQ(library_term(library, "√|x|").factors[0].value(-9.0), 3.0);
  EXPECT_EQ(root.factors[0].exponent(), 0.5);
  EXPECT_EQ(rate_of(Eigen::Vector3d(1.0, 3.0, 2.0), 0.5), Eigen::Vector3d(0.0, 4.0, -2.0));  // none before the record
}

TEST(TermLibrary, ProductsAcrossTheChainEnterWhereTheirLaterSignalLives) {
  const auto library = term_library(3);
  const auto find = [&](const std::string& text) { return library_term(library, text); };
  EXPECT_EQ(find("v·x'").stage, TermStage::Dynamics);
  EXPECT_EQ(find("|w|·y").stage, TermStage::Output);
  EXPECT_EQ(find("v·w").stage, TermStage::Static);
  EXPECT_FALSE(find("v·x'").of_one_signal());
  EXPECT_FALSE(find("play(v, 25 %)").of_one_signal());
  EXPECT_TRUE(find("w³").of_one_signal());  // the static block's output, its own signal
  EXPECT_EQ(find("play(v, 25 %)").entry(), Model::Entry::Dynamics);
}

TEST(TermLibrary, FactorsAreBuiltFromTheChainsSignalsAndTheirRates) {
  Measurement m;
  m.t = Eigen::VectorXd::LinSpaced(5, 0.0, 2.0);
  m.u = (Eigen::VectorXd(5) << 0.0, 1.0, 3.0, 2.0, -1.0).finished();
  m.y = m.u;
  m.sample_time = 0.5;
  ModelData data(m, SignalScales{});
  data.estimation << 1.0, 1.0, 1.0, 1.0, 0.0;  // the last sample held out
  Model::ChainSignals chain;
  chain.v = (Eigen::VectorXd(5) << 0.0, 2.0, 4.0, 2.0, -8.0).finished();
  chain.w = chain.resonance = chain.x = chain.v;
  EXPECT_EQ(factor_signal({TermSignal::Input, true, 1, true}, data, chain), rate_of(m.u, 0.5));
  EXPECT_EQ(factor_signal({TermSignal::Drive, false, 1, true}, data, chain), chain.v);
  // Radius 25 % of max |v| on the estimation samples (4, not the held-out 8): 1.
  EXPECT_EQ(factor_signal({TermSignal::Play, false, 1, true, 0.25}, data, chain), play_operator(chain.v, 1.0));
  EXPECT_EQ((TermFactor{TermSignal::Play, true, 1, true, 0.25}.symbol()), "play(v, 25 %)'");
}

TEST(TermLibrary, PlayOperatorFollowsTheInputOnlyBeyondItsRadius) {
  const Eigen::VectorXd a = (Eigen::VectorXd(7) << 0.0, 0.5, 1.5, 1.0, 0.25, -1.0, 0.0).finished();
  const Eigen::VectorXd p = play_operator(a, 0.5);
  // From 0: held until a passes 0.5 above, then a − 0.5; held on the way back
  // until a passes 0.5 below, then a + 0.5.
  const Eigen::VectorXd expected = (Eigen::VectorXd(7) << 0.0, 0.0, 1.0, 1.0, 0.75, -0.5, -0.5).finished();
  EXPECT_EQ(p, expected);
}

TEST(EffectSource, NamesTheTermAndRefusesAForceWithoutMsd) {
  ProposedTerm t;
  t.term = {TermStage::Static, {{TermSignal::Drive, false, 1, true}, {TermSignal::Drive, true, 1, false}}};
  t.coefficient = 0.002;
  const std::string source = proposed_effect_source(t, {"rate_gain", "data.csv", "hysteresis,msd"});
  EXPECT_NE(source.find("HYSTBENCH_EFFECT(RateGain)"), std::string::npos);
  EXPECT_NE(source.find("EffectStage::Nonlinearity"), std::string::npos);
  EXPECT_NE(source.find("-0.02, 0.02, 0"), std::string::npos);  // c within ten times the proposal
  EXPECT_NE(source.find("proposed from data"), std::string::npos);
  t.term = {TermStage::Dynamics, {{TermSignal::Resonance, false, 1, true}, {TermSignal::Resonance, true, 1, false}}};
  EXPECT_NE(proposed_effect_source(t, {"stiff", "data.csv", "msd"}).find("i.extends = \"msd\""),
            std::string::npos);
  EXPECT_THROW(proposed_effect_source(t, {"stiff", "data.csv", "hysteresis,arx"}), InputError);
  ProposedTerm of_w = t;
  of_w.term = {TermStage::Static, {{TermSignal::StaticOutput, false, 3, true}}};
  const std::string w_source = proposed_effect_source(of_w, {"stiff_w", "data.csv", "hysteresis,msd"});
  EXPECT_NE(w_source.find("const V a = signal, b = V{};"), std::string::npos);  // built from w itself
  EXPECT_NE(w_source.find("KernelEffect<StiffW, 1, hystbench::EffectDrive::None>"), std::string::npos);  // batched
  EXPECT_NE(w_source.find("c·w³"), std::string::npos);
  EXPECT_NE(w_source.find("-0.02, 0.02, 0, -2, 0, \"\""), std::string::npos);  // c in units of y⁻²
  // A product of two signals the block sees: v and w in the static block.
  ProposedTerm static_product = t;
  static_product.term = {TermStage::Static, {{TermSignal::Drive, true, 1, false}, {TermSignal::StaticOutput, false, 1, true}}};
  const std::string p_source = proposed_effect_source(static_product, {"rate_w", "data.csv", "asymmetry,msd"});
  EXPECT_NE(p_source.find("const V a = signal, b = V{} + drive;"), std::string::npos) << p_source;
  EXPECT_NE(p_source.find("KernelEffect<RateW, 1, hystbench::EffectDrive::StageInput>"), std::string::npos);
  EXPECT_NE(p_source.find("factor(a, 1, true) * factor(a_rate, 0, false) * factor(b_rate, 1, false)"),
            std::string::npos);
  EXPECT_NE(p_source.find("-0.02, 0.02, 0, 0, -1, \"s\""), std::string::npos);  // c·|v'|·w in w: units s/u
  // A force of the drive and the resonance: with the gain alone in the
  // static block it is written with w = gain·v, c divided by the gain.
  ProposedTerm cross = t;
  cross.term = {TermStage::Dynamics, {{TermSignal::Drive, false, 1, false}, {TermSignal::Resonance, false, 1, true}}};
  const std::string c_source = proposed_effect_source(cross, {"stiff", "data.csv", "msd", -2.0});
  EXPECT_NE(c_source.find("c·x·|w|"), std::string::npos) << c_source;
  EXPECT_NE(c_source.find("the term |v|·x at the dynamics stage"), std::string::npos);
  EXPECT_NE(c_source.find("-0.01, 0.01, 0, -1, 0, \"\""), std::string::npos);  // 0.002 / |−2|, in units of y⁻¹
  EXPECT_NE(c_source.find("EffectDrive::StageInput"), std::string::npos);
  const auto refusal = [&](const ProposedTerm& term, const std::string& model) {
    try {
      proposed_effect_source(term, {"stiff", "data.csv", model});
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no refusal");
  };
  EXPECT_NE(refusal(cross, "asymmetry,msd").find("|v|·x pairs the drive v with the resonance's output"),
            std::string::npos);
  ProposedTerm at_output = t;
  at_output.term = {TermStage::Output, {{TermSignal::Resonance, false, 1, true}, {TermSignal::Output, true, 1, true}}};
  EXPECT_NE(refusal(at_output, "msd").find("which an effect of that block does not see"), std::string::npos);
  ProposedTerm play = t;
  play.term = {TermStage::Static, {{TermSignal::Play, false, 1, true, 0.25}}};
  EXPECT_NE(refusal(play, "msd").find("is neither a power of one signal"), std::string::npos);
  ProposedTerm root = t;
  root.term = {TermStage::Output, {{TermSignal::Output, false, 1, true, 0.0, true}}};
  const std::string root_source = proposed_effect_source(root, {"orifice", "data.csv", "msd"});
  EXPECT_NE(root_source.find("factor(a, 1, true, true)"), std::string::npos);  // sign(y)·√|y|
  EXPECT_NE(root_source.find("\"normalised units\""), std::string::npos);   // c has a half power of y
  EXPECT_THROW(check_effect_name("msd"), InputError);
  EXPECT_THROW(check_effect_name("Bad-Name"), InputError);
}

TEST(BeyondCatalog, ExcessShareIsWhatACandidateRemovesAboveTheNoise) {
  EXPECT_DOUBLE_EQ(excess_share(5.0, 3.0, 0.0), 16.0 / 25.0);
  EXPECT_DOUBLE_EQ(excess_share(5.0, 4.0, 3.0), 9.0 / 16.0);
  EXPECT_TRUE(std::isnan(excess_share(1.0, 0.9, 1.0)));
}

// A candidate that removes `after` of a held-out RMSE of 5 above a noise of 3
// (an excess of 16).
Diagnosis systematic_with(double after) {
  Diagnosis d{Model::parse("msd"), {}, {}};
  d.errors.n_heldout = 100;
  d.errors.rmse_heldout = 5.0;
  d.completeness.kind = "systematic";
  d.completeness.sigma = 3.0;
  Candidate c{"creep", Model::parse("msd,creep"), {}, {}};
  c.after.n_heldout = 100;
  c.after.rmse_heldout = after;
  d.candidates.push_back(c);
  return d;
}

TEST(BeyondCatalog, LeadersAreRefitOnlyWhenOneCouldReachTheStoppingShare) {
  EXPECT_FALSE(refit_could_pass(systematic_with(4.9)));  // (25 - 24.01) / 16: 6 %
  EXPECT_TRUE(refit_could_pass(systematic_with(4.8)));   // (25 - 23.04) / 16: 12 %
  Diagnosis at_floor = systematic_with(4.9);
  at_floor.completeness.kind = "coloured_at_floor";  // the partial-help rule does not apply there
  EXPECT_TRUE(refit_could_pass(at_floor));
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
  // The same term at the input, and of w = gain·v, is one column here (only
  // the gain between): the static block's drive is said.
  EXPECT_TRUE(p.terms[0].runner_up == "input: u·|u'|" || p.terms[0].runner_up == "static: w·|w'|")
      << p.terms[0].runner_up;
  EXPECT_LT(p.rmse_heldout_after, 1.2 * s.noise);
  EXPECT_GT(p.rmse_heldout, 5.0 * s.noise);
}

// propose_terms on msd fitted to `s`: its first term is `text` at `stage`,
// and the terms bring the held-out RMSE within 1.2 × the noise.
Proposal expect_first_proposal(const planted::System& s, const std::string& text, TermStage stage) {
  const PlantedFit f = fit_planted(s, "msd");
  const Proposal p = propose_terms(f.model, f.x, f.data);
  EXPECT_LT(p.rmse_heldout_after, 1.2 * s.noise);
  if (p.terms.empty()) {
    ADD_FAILURE() << "nothing proposed; expected " << text;
    return p;
  }
  EXPECT_EQ(p.terms[0].term.text(), text);
  EXPECT_EQ(p.terms[0].term.stage, stage);
  EXPECT_FALSE(p.falls_short) << beyond_library(p);
  EXPECT_NEAR(p.noise_sd, s.noise, 0.3 * s.noise);
  return p;
}

TEST(Proposal, PlantedCubicStiffnessIsProposedInsideTheDynamics) {
  planted::System s;
  s.cubic = 0.01;
  const Proposal p = expect_first_proposal(s, "x³", TermStage::Dynamics);
  if (!p.terms.empty()) {
    EXPECT_LT(p.terms[0].coefficient, 0.0);  // a hardening spring: a restoring force
  }
}

TEST(Proposal, PlantedPlayBesideTheGainIsProposedAsTheStateOfAPlayOperator) {
  planted::System s;
  s.play_gain = 0.2;  // radius 25 % of max |u|, one of the library's
  const Proposal p = expect_first_proposal(s, "play(v, 25 %)", TermStage::Static);
  EXPECT_GT(p.rmse_heldout, 3.0 * s.noise);
}

TEST(Proposal, PlantedDriveDependentStiffnessIsProposedAsAProductAcrossTheChain) {
  planted::System s;
  s.drive_stiffness = 0.03;
  // w = gain·v here, so |v|·x and |w|·x are one column: the drive is said.
  const Proposal p = expect_first_proposal(s, "|v|·x", TermStage::Dynamics);
  if (!p.terms.empty()) {
    EXPECT_LT(p.terms[0].coefficient, 0.0);  // a restoring force
  }
}

TEST(Proposal, PlantedQuadraticDampingIsProposedAsADragInsideTheDynamics) {
  planted::System s;
  s.quadratic_damping = 1e-6;
  const Proposal p = expect_first_proposal(s, "x'·|x'|", TermStage::Dynamics);
  if (!p.terms.empty()) {
    EXPECT_LT(p.terms[0].coefficient, 0.0);  // against the motion: it takes energy out
  }
}

TEST(Proposal, PlantedSquareRootSensorLawIsProposedAtTheOutput) {
  planted::System s;
  s.root_gain = 0.1;
  const Proposal p = expect_first_proposal(s, "sign(y)·√|y|", TermStage::Output);
  if (!p.terms.empty()) {
    EXPECT_GT(p.terms[0].coefficient, 0.0);
  }
}

// propose_terms on msd fitted to `s`: the library falls short, and says so
// with `why` among its reasons, instead of passing a partial term off as
// the answer.
void expect_beyond_library(const planted::System& s, const std::string& why) {
  const PlantedFit f = fit_planted(s, "msd");
  const Proposal p = propose_terms(f.model, f.x, f.data);
  EXPECT_TRUE(p.falls_short);
  EXPECT_GT(p.rmse_heldout_after, kLibraryShort * p.noise_sd);
  EXPECT_NEAR(p.noise_sd, s.noise, 0.3 * s.noise);
  const std::string text = beyond_library(p);
  EXPECT_NE(text.find("The library cannot express what is missing"), std::string::npos) << text;
  EXPECT_NE(text.find(why), std::string::npos) << text;
  EXPECT_EQ(p.to_json()["beyond_library"].get<std::string>(), text);
}

// A gain that drifts with time (30 % over the record): no term of the
// library is a function of time.
TEST(Proposal, PlantedGainDriftIsSaidToBeBeyondTheLibrary) {
  planted::System s;
  s.gain_drift = 0.05;
  expect_beyond_library(s, "a law that changes with time");
}

// Dry friction, a force that jumps with the direction of motion: the odd
// powers of the speed the library offers are zero at rest.
TEST(Proposal, PlantedCoulombFrictionIsSaidToBeBeyondTheLibrary) {
  planted::System s;
  s.coulomb = 0.05;
  expect_beyond_library(s, "a friction force that jumps with the direction of motion");
}

// A play operator whose width grows with the drive rate: the library's play
// operators have fixed radii.
TEST(Proposal, PlantedRateDependentPlayIsSaidToBeBeyondTheLibrary) {
  planted::System s;
  s.play_gain = 0.2;
  s.play_radius = 0.1;
  s.play_width_rate = 0.01;
  expect_beyond_library(s, "a loop whose width changes with the drive's rate");
}

TEST(Proposal, NothingIsProposedWhenTheModelIsRight) {
  planted::System s;  // no planted term: msd is the truth
  const PlantedFit f = fit_planted(s, "msd");
  const Proposal p = propose_terms(f.model, f.x, f.data);
  EXPECT_TRUE(p.terms.empty()) << p.terms[0].term.text() << ": held-out RMSE " << p.rmse_heldout << " -> "
                               << p.terms[0].heldout_rmse;
}

}  // namespace
}  // namespace hystbench
