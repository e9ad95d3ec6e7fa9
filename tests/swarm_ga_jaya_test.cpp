// GA, PSO, Jaya and hybrid Jaya: known optima, reproducibility, exact
// budgets, and the shared operators checked by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "framework/harness/experiment.hpp"
#include "framework/harness/trial_runner.hpp"
#include "framework/evolution/jaya_operators.hpp"
#include "framework/evolution/normalised_space.hpp"
#include "framework/evolution/population.hpp"
#include "framework/evolution/pso_coefficients.hpp"
#include "framework/evolution/real_coded_operators.hpp"
#include "problems/functions/function_problem.hpp"

namespace hystbench {
namespace {

struct Algorithm {
  const char* name;
  nlohmann::json params;
};

// Every plugin of this file with its default parameters (PSO twice).
const std::vector<Algorithm>& defaults() {
  static const std::vector<Algorithm> all{{"ga", nlohmann::json::object()},
                                          {"pso", {{"variant", "inertia"}}},
                                          {"pso", {{"variant", "constriction"}}},
                                          {"jaya", nlohmann::json::object()},
                                          {"hybrid_jaya", nlohmann::json::object()}};
  return all;
}

std::string label(const Algorithm& a) { return std::string(a.name) + " " + a.params.dump(); }

Experiment experiment(const Algorithm& a, long evaluations) {
  const nlohmann::json problem = {{"type", "function"}, {"name", "sphere"}, {"dimension", 2}};
  return Experiment::from_json({{"name", "t"},
                                {"problem", problem},
                                {"budget", {{"evaluations", evaluations}}},
                                {"trials", 1},
                                {"seed", 11},
                                {"algorithms", {{{"name", a.name}, {"params", a.params}}}}},
                               "test");
}

TrialResult run(const Problem& problem, const Algorithm& a, long evaluations, long trial = 0) {
  const auto r = run_trial(problem, experiment(a, evaluations), 0, trial);
  EXPECT_FALSE(r.failed()) << label(a) << ": " << r.message;
  return r;
}

// --- whole algorithms ------------------------------------------------------

TEST(SwarmGaJaya, ReachTheSphereOptimumWithDefaults) {
  FunctionProblem sphere("sphere", 10);
  for (const auto& a : defaults()) {
    if (std::string(a.name) == "ga") continue;  // see the next test
    const auto r = run(sphere, a, 50000);
    EXPECT_LT(r.best, 1e-6) << label(a);
    EXPECT_LE(r.evaluations, 50000) << label(a);
  }
}

TEST(SwarmGaJaya, GaApproachesTheSphereOptimumSlowly) {
  // The GA of docs/algorithms.md#ga does not reach 1e-6 on sphere-10 (box
  // [-100, 100]) in 50 000 evaluations. Measured best values, trials 0-4 of
  // this experiment: 2.5e-3, 3.8e-3, 1.5e-2, 1.1e-2, 2.0e-2 (median 1.1e-2);
  // of another seed: 2.8e-3 .. 1.8e-2 (median 3.0e-3). Polynomial mutation
  // (eta_m 20, p_m 1/D) moves about two thirds of the children by a few % of
  // the range, and generational replacement with 2 elites keeps that noise in
  // the population; an independent implementation reaches the same level.
  // Assert the measured level with a margin (the initial best is ~1e4).
  FunctionProblem sphere("sphere", 10);
  const Algorithm ga{"ga", nlohmann::json::object()};
  std::vector<double> best;
  for (long trial = 0; trial < 5; ++trial) best.push_back(run(sphere, ga, 50000, trial).best);
  std::sort(best.begin(), best.end());
  EXPECT_LT(best[2], 0.03);
  EXPECT_LT(best[4], 0.1);
}

TEST(SwarmGaJaya, GaWithPlusReplacementConvergesFurther) {
  // Plus replacement is pagmo's sga: parents and children pooled, the best N
  // kept, and sga's polynomial mutation, which steps towards a bound by a
  // share of the distance to it. Pooling keeps the mutation noise out of the
  // population, the shorter steps near the optimum do the rest: the same
  // experiment and trials as the test above end about a hundred times lower.
  // Measured best values of trials 0-4, sorted: 4.3e-5, 8.5e-5, 1.1e-4,
  // 1.3e-4, 2.4e-4 (median 1.1e-4; with the NSGA-II mutation of the
  // generational GA the median is about 4e-4, and pagmo's sga reaches 1.3e-4
  // over 30 trials, results/performance/peer.md).
  FunctionProblem sphere("sphere", 10);
  const Algorithm ga{"ga", {{"replacement", "plus"}}};
  std::vector<double> best;
  for (long trial = 0; trial < 5; ++trial) best.push_back(run(sphere, ga, 50000, trial).best);
  std::sort(best.begin(), best.end());
  EXPECT_LT(best[2], 3e-4);
  EXPECT_LT(best[4], 1e-3);
}

TEST(SwarmGaJaya, ImproveOnRastrigin) {
  // A uniform point of rastrigin-5 scores about 90; the best of the
  // initial population about 40.
  FunctionProblem rastrigin("rastrigin", 5);
  for (const auto& a : defaults()) {
    const auto r = run(rastrigin, a, 20000);
    EXPECT_LT(r.best, 10.0) << label(a);
  }
}

long evaluations_after_iterations(const Algorithm& a, long iterations) {
  FunctionProblem sphere("sphere", 3);
  auto e = experiment(a, 1);
  e.budget.evaluations.reset();
  e.budget.iterations = iterations;
  const auto r = run_trial(sphere, e, 0, 0);
  EXPECT_EQ(r.iterations, iterations);
  return r.evaluations;
}

TEST(SwarmGaJaya, EvaluationsPerIteration) {
  // GA: N initial, then N - E offspring; hybrid Jaya: two phases of NP each.
  EXPECT_EQ(evaluations_after_iterations({"ga", nlohmann::json::object()}, 10), 100 + 10 * 98);
  EXPECT_EQ(evaluations_after_iterations({"ga", {{"np", 21}, {"elites", 0}}}, 3), 21 + 3 * 21);
  // Plus replacement breeds N children whatever the elites.
  EXPECT_EQ(evaluations_after_iterations({"ga", {{"replacement", "plus"}}}, 10), 100 + 10 * 100);
  EXPECT_EQ(evaluations_after_iterations({"pso", nlohmann::json::object()}, 10), 40 + 10 * 40);
  EXPECT_EQ(evaluations_after_iterations({"jaya", nlohmann::json::object()}, 10), 50 + 10 * 50);
  EXPECT_EQ(evaluations_after_iterations({"hybrid_jaya", nlohmann::json::object()}, 10),
            50 + 10 * 100);
}

TEST(SwarmGaJaya, SwitchableOperatorsAndTopologiesWork) {
  FunctionProblem rastrigin("rastrigin", 5);
  const std::vector<Algorithm> options{
      {"ga", {{"crossover", "blx-alpha"}}},
      {"ga", {{"crossover", "arithmetic"}}},
      {"ga", {{"mutation", "gaussian"}}},
      {"ga", {{"tournament", 4}, {"elites", 0}}},
      {"ga", {{"replacement", "plus"}, {"crossover", "blx-alpha"}}},
      {"pso", {{"topology", "ring"}}},
      {"pso", {{"bounds", "reflect"}}},
      {"pso", {{"variant", "constriction"}, {"topology", "ring"}, {"bounds", "reflect"}}}};
  for (const auto& a : options) {
    const auto r = run(rastrigin, a, 20000);
    EXPECT_LT(r.best, 10.0) << label(a);
  }
}

// Checks across parameters run when the experiment is loaded, so a bad
// combination is refused before any output exists.
std::string load_error(const Algorithm& algorithm) {
  try {
    experiment(algorithm, 100);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(SwarmGaJaya, RejectsInconsistentParameters) {
  EXPECT_NE(load_error({"ga", {{"np", 10}, {"elites", 10}}})
                .find("algorithms[0] (ga).params: ga: elites = 10 must be smaller than np = 10"),
            std::string::npos);
  EXPECT_NE(load_error({"ga", {{"np", 10}, {"tournament", 11}}})
                .find("ga: tournament = 11 must not exceed np = 10"),
            std::string::npos);
  EXPECT_NE(load_error({"pso", {{"variant", "constriction"}, {"c1", 2}, {"c2", 2}}})
                .find("pso: the constriction variant needs c1 + c2 > 4; got c1 = 2, c2 = 2"),
            std::string::npos);
  EXPECT_NE(load_error({"hybrid_jaya", {{"np", 3}}}).find("np = 3 is out of range; it must be in [4, 100000]"),
            std::string::npos);
}

// --- shared operators ------------------------------------------------------

Bounds box(double lo, double hi, int d) {
  Bounds b;
  b.lower = Eigen::VectorXd::Constant(d, lo);
  b.upper = Eigen::VectorXd::Constant(d, hi);
  return b;
}

TEST(RealCodedOperators, SbxChildrenStayInsideAndKeepTheMeanOfCentredParents) {
  const Bounds b = box(-1.0, 1.0, 4);
  Rng rng(3);
  Eigen::VectorXd y1(4), y2(4);
  y1 << -0.3, -0.9, 0.5, -1.0;
  y2 << 0.3, 0.9, -0.5, 1.0;  // each pair symmetric about the centre of the box
  bool moved = false;
  for (int t = 0; t < 2000; ++t) {
    const auto [c1, c2] = sbx_crossover(y1, y2, b, 20.0, rng);
    EXPECT_TRUE(b.contains(c1) && b.contains(c2));
    // Equal distances to both bounds give both children the same spread.
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(c1[j], -c2[j], 1e-12);
    moved = moved || c1 != y1;
  }
  EXPECT_TRUE(moved);
}

TEST(RealCodedOperators, SbxLeavesEqualParentsAlone) {
  const Bounds b = box(0.0, 1.0, 3);
  Rng rng(4);
  const Eigen::VectorXd y = Eigen::VectorXd::Constant(3, 0.25);
  const auto [c1, c2] = sbx_crossover(y, y, b, 20.0, rng);
  EXPECT_EQ(c1, y);
  EXPECT_EQ(c2, y);
}

TEST(RealCodedOperators, PolynomialMutationRespectsBoundsAndProbability) {
  const Bounds b = box(0.0, 1.0, 3);
  Rng rng(5);
  Eigen::VectorXd y(3);
  y << 0.0, 0.5, 1.0;
  Eigen::VectorXd same = y;
  polynomial_mutation(same, b, 0.0, 20.0, rng);
  EXPECT_EQ(same, y);
  for (int t = 0; t < 2000; ++t) {
    Eigen::VectorXd m = y;
    polynomial_mutation(m, b, 1.0, 20.0, rng);
    EXPECT_TRUE(b.contains(m));
    EXPECT_NE(m[1], 0.5);
  }
}

TEST(RealCodedOperators, PolynomialMutationMatchesTheFormula) {
  // y = 0.25 in [0, 1], eta 20: with r < 0.5,
  // dq = (2r + (1 - 2r)(1 - 0.25)^21)^(1/21) - 1.
  const Bounds b = box(0.0, 1.0, 1);
  Rng rng(6), copy(6);
  Eigen::VectorXd y = Eigen::VectorXd::Constant(1, 0.25);
  polynomial_mutation(y, b, 1.0, 20.0, rng);
  copy.uniform();  // the p_m draw
  const double r = copy.uniform();
  const double m = 1 / 21.0;
  const double dq = r < 0.5 ? std::pow(2 * r + (1 - 2 * r) * std::pow(0.75, 21.0), m) - 1
                            : 1 - std::pow(2 * (1 - r) + 2 * (r - 0.5) * std::pow(0.25, 21.0), m);
  EXPECT_DOUBLE_EQ(y[0], 0.25 + dq);
}

TEST(RealCodedOperators, PolynomialMutationToBoundMatchesTheFormula) {
  // y = 0.25 in [0, 1], eta 20, as pagmo's sga: with r <= 0.5 the step is
  // ((2r)^(1/21) - 1) * (y - 0), else (1 - (2(1 - r))^(1/21)) * (1 - y).
  const Bounds b = box(0.0, 1.0, 1);
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    Rng rng(seed), copy(seed);
    Eigen::VectorXd y = Eigen::VectorXd::Constant(1, 0.25);
    polynomial_mutation_to_bound(y, b, 1.0, 20.0, rng);
    copy.uniform();  // the p_m draw
    const double r = copy.uniform(), m = 1 / 21.0;
    const double step = r <= 0.5 ? (std::pow(2 * r, m) - 1) * 0.25 : (1 - std::pow(2 * (1 - r), m)) * 0.75;
    EXPECT_DOUBLE_EQ(y[0], 0.25 + step) << "seed " << seed;
  }
}

// In the middle of the box [-100, 100] the to-bound form scales delta by 100,
// the NSGA-II form by the width 200: with eta 20 the median |step| is
// 100 (1 - 0.5^(1/21)) = 3.247 against twice that.
TEST(RealCodedOperators, PolynomialMutationToBoundTakesHalfTheStepsInTheMiddle) {
  const Bounds b = box(-100.0, 100.0, 1);
  Rng rng(9);
  std::vector<double> to_bound, nsga2;
  for (int t = 0; t < 20001; ++t) {
    Eigen::VectorXd y = Eigen::VectorXd::Zero(1), z = Eigen::VectorXd::Zero(1);
    polynomial_mutation_to_bound(y, b, 1.0, 20.0, rng);
    polynomial_mutation(z, b, 1.0, 20.0, rng);
    to_bound.push_back(std::abs(y[0]));
    nsga2.push_back(std::abs(z[0]));
  }
  const auto median = [](std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
    return v[v.size() / 2];
  };
  const double expected = 100 * (1 - std::pow(0.5, 1 / 21.0));
  EXPECT_NEAR(median(to_bound), expected, 0.03 * expected);
  EXPECT_NEAR(median(nsga2), 2 * expected, 0.06 * expected);
}

TEST(RealCodedOperators, TournamentPicksTheBestAndBreaksTiesAtRandom) {
  Rng rng(7);
  Eigen::VectorXd f(5);
  f << 3.0, 1.0, INFINITY, 2.0, 5.0;
  EXPECT_EQ(tournament(f, 5, rng), 1);
  const Eigen::VectorXd flat = Eigen::VectorXd::Constant(3, 1.0);
  std::set<int> winners;
  for (int t = 0; t < 100; ++t) winners.insert(tournament(flat, 3, rng));
  EXPECT_EQ(winners.size(), 3u);
}

TEST(PsoCoefficients, ScheduleEndsAndConstriction) {
  EXPECT_DOUBLE_EQ(inertia_weight(0.9, 0.4, 0.0), 0.9);
  EXPECT_DOUBLE_EQ(inertia_weight(0.9, 0.4, 1.0), 0.4);
  EXPECT_DOUBLE_EQ(inertia_weight(0.9, 0.4, 0.5), 0.65);
  EXPECT_NEAR(constriction_factor(4.1), 0.7298437881, 1e-10);
  EXPECT_NEAR(constriction_factor(4.1) * 2.05, 1.4962, 1e-4);
  EXPECT_THROW(constriction_factor(4.0), std::invalid_argument);
}

TEST(NormalisedSpace, MapsTheUnitCubeOntoTheBox) {
  Bounds b;
  b.lower = Eigen::Vector3d(-2.0, 0.1, 5.0);
  b.upper = Eigen::Vector3d(3.0, 0.3, 5.0);  // last parameter fixed
  const NormalisedSpace space(b);
  Eigen::MatrixXd Z(3, 2);
  Z << 0.0, 1.0, 0.5, 1.0, 0.7, 0.2;
  const Eigen::MatrixXd X = space.to_box(Z);
  EXPECT_EQ(X.col(0), Eigen::Vector3d(-2.0, 0.2, 5.0));
  EXPECT_EQ(X.col(1), b.upper);
  const Eigen::MatrixXd back = space.to_unit(X);
  EXPECT_NEAR(back(1, 0), 0.5, 1e-12);
  EXPECT_EQ(back(2, 0), 0.0);
  // Same draws as a population sampled in the box: common random numbers
  // with the methods that do not normalise.
  Rng a(8), c(8);
  EXPECT_EQ(space.to_box(uniform_population(space.unit(), 4, a)), uniform_population(b, 4, c));
}

TEST(JayaOperators, MoveTowardTheBestAndAwayFromTheWorst) {
  const Bounds unit = box(0.0, 1.0, 2);
  Eigen::MatrixXd X(2, 3);
  X << 0.2, 0.6, 0.9,  //
      0.5, 0.4, 0.1;
  Eigen::VectorXd f(3);
  f << 1.0, 0.5, 4.0;  // best = member 1, worst = member 2
  Rng rng(9), copy(9);
  const Eigen::MatrixXd U = jaya_candidates(X, f, unit, rng);
  for (int k = 0; k < 3; ++k) {
    for (int j = 0; j < 2; ++j) {
      const double r1 = copy.uniform(), r2 = copy.uniform();
      const double v = X(j, k) + r1 * (X(j, 1) - X(j, k)) - r2 * (X(j, 2) - X(j, k));
      EXPECT_EQ(U(j, k), std::clamp(v, 0.0, 1.0)) << k << "," << j;
    }
  }
}

}  // namespace
}  // namespace hystbench
