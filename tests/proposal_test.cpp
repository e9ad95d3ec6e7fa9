// Proposing a missing term: orthogonal forward regression on known columns,
// the term library, and `propose` on actuators with planted physics the
// catalog lacks (tests/planted_physics.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "framework/discovery/model_fit.hpp"
#include "framework/discovery/proposal.hpp"
#include "framework/model/holdout.hpp"
#include "framework/stats/forward_regression.hpp"
#include "tests/planted_physics.hpp"

namespace hystbench {
namespace {

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
  const FitResult r = fit_model(f.model, f.data, o);
  f.x = r.x;
  std::cout << "fit sse " << r.sse << " evals " << r.evaluations << " s " << r.seconds << " y rms " << f.data.scales.y << "\n";
  return f;
}

TEST(Proposal, PlantedRateDependentGainIsProposedAtTheStaticBlock) {
  planted::System s;
  s.rate_gain = 0.001;
  const PlantedFit f = fit_planted(s, "msd");
  const Proposal p = propose_terms(f.model, f.x, f.data);
  std::cout << p.to_json().dump(1) << "\n";
  ASSERT_FALSE(p.terms.empty());
  EXPECT_EQ(p.terms[0].term.text(), "v·|v'|");
  EXPECT_EQ(term_stage_name(p.terms[0].term.stage), "static");
}

TEST(Proposal, PlantedCubicStiffnessIsProposedInsideTheDynamics) {
  planted::System s;
  s.cubic = 0.01;
  const PlantedFit f = fit_planted(s, "msd");
  const Proposal p = propose_terms(f.model, f.x, f.data);
  std::cout << p.to_json().dump(1) << "\n";
  ASSERT_FALSE(p.terms.empty());
  EXPECT_EQ(p.terms[0].term.text(), "x³");
  EXPECT_EQ(term_stage_name(p.terms[0].term.stage), "dynamics");
}

}  // namespace
}  // namespace hystbench
