#include "framework/discovery/candidates_figure.hpp"

#include <gtest/gtest.h>

#include "tests/temp_dir.hpp"

namespace hystbench {
namespace {

using test_support::contains;
using test_support::read;
using test_support::TempDir;

// Current model: estimation RMSE 50, held-out RMSE 40 (over `heldout`
// samples), noise floor 1.
Diagnosis diagnosis(long heldout) {
  FitErrors current;
  current.n_estimation = 100;
  current.n_heldout = heldout;
  current.rmse_estimation = 50;
  current.rmse_heldout = heldout ? 40 : 0;
  Diagnosis d{Model::parse("hysteresis"), Eigen::VectorXd(), current};
  d.where.noise_floor.sigma = 1.0;
  for (const char* effect : {"feedback_hysteresis", "offset"}) {
    FitErrors after;
    after.rmse_estimation = 20;
    after.rmse_heldout = 30;
    d.candidates.push_back(
        {effect, Model::parse(std::string("hysteresis,") + effect), Eigen::VectorXd(), after});
  }
  return d;
}

TEST(CandidatesFigure, EachKindOfBarIsMarkedWithTheCurrentErrorOfItsKind) {
  TempDir dir;
  const std::string gp = read(write_candidates_figure(dir.path(), diagnosis(25), "µm"));
  EXPECT_TRUE(contains(gp, "\ncurrent_estimation = 50 ")) << gp;
  EXPECT_TRUE(contains(gp, "\ncurrent_heldout = 40 ")) << gp;
  EXPECT_TRUE(contains(gp, "\nsigma = 1 ")) << gp;
  // Estimation bars (column 2) left of the tic, held-out bars (column 3)
  // right of it, each 0.36 wide; the marks span the same x and sit at the
  // current value of their own kind.
  for (const char* part :
       {"using ($0 - 0.19):2:xtic(1) with boxes lc rgb '#0072B2' title 'estimation'",
        "using ($0 - 0.37):(current_estimation):(bar):(0) with vectors nohead lw 3 "
        "lc rgb '#0072B2' title 'current, estimation'",
        "using ($0 + 0.19):3 with boxes lc rgb '#D55E00' title 'held out'",
        "using ($0 + 0.01):(current_heldout):(bar):(0) with vectors nohead lw 3 "
        "lc rgb '#D55E00' title 'current, held out'",
        "\nbar = 0.36 "})
    EXPECT_TRUE(contains(gp, part)) << part << " missing from:\n" << gp;
  // Room on the left for "feedback_hysteresis" (19 letters) turned 45 degrees.
  EXPECT_TRUE(contains(gp, "set lmargin 14\n")) << gp;
  EXPECT_TRUE(contains(gp, "set xtics rotate by 45 right")) << gp;
}

TEST(CandidatesFigure, WithoutHeldOutDataOnlyEstimationBars) {
  TempDir dir;
  const std::string gp = read(write_candidates_figure(dir.path(), diagnosis(0), ""));
  EXPECT_TRUE(contains(gp, "# No held-out data: estimation bars only.\n")) << gp;
  EXPECT_TRUE(contains(gp, "using ($0):2:xtic(1)")) << gp;
  EXPECT_FALSE(contains(gp, "held out")) << gp;
  EXPECT_FALSE(contains(gp, "current_heldout")) << gp;
}

}  // namespace
}  // namespace hystbench
