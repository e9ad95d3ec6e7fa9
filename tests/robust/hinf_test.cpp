// The SLICOT layer against SLICOT's own published examples: the SB10FD
// controller of its documentation (6 states, gamma = 15), AB13DD's peak of
// a lightly damped system, and the search's closed loop checked by the
// norm it promises; bad plants give messages that name the assumption.
#include <gtest/gtest.h>

#include "framework/core/eigen.hpp"
#include <cmath>
#include <string>

#include "framework/core/error.hpp"
#include "framework/robust/hinf_norm.hpp"
#include "framework/robust/hinf_synthesis.hpp"
#include "tests/robust/slicot_examples.hpp"

namespace hystbench::robust {
namespace {

using examples::rows;
StateSpace sb10fd_example() { return examples::sb10fd_plant(); }


double max_real_pole(const Eigen::MatrixXd& A) { return Eigen::EigenSolver<Eigen::MatrixXd>(A).eigenvalues().real().maxCoeff(); }

TEST(HinfSynthesis, ReproducesSlicotsPublishedControllerAtGamma15) {
  HinfOptions o;
  o.fixed_gamma = 15.0;
  const HinfController k = hinf_synthesis(sb10fd_example(), 2, 2, o);
  // The documentation prints four decimals.
  EXPECT_NEAR(k.controller.A(0, 0), -2.8043, 1e-3);
  EXPECT_NEAR(k.controller.A(4, 0), 30.6789, 1e-3);
  EXPECT_NEAR(k.controller.B(1, 0), -0.9237, 1e-3);
  EXPECT_NEAR(k.controller.C(1, 0), 2.8810, 1e-3);
  const Eigen::MatrixXd dk = rows(2, 2, {0.0554, 0.1334, -0.3195, 0.0333});
  EXPECT_LT((k.controller.D - dk).cwiseAbs().maxCoeff(), 1e-3) << k.controller.D;
  EXPECT_NEAR(k.rcond[2], 0.011241, 1e-5);
  // Its closed-loop poles: the slowest is -1.7178.
  EXPECT_NEAR(max_real_pole(k.closed_loop.A), -1.7178, 1e-3);
  EXPECT_LE(hinf_norm(k.closed_loop, TimeDomain::Continuous).norm, 15.0);
}

TEST(HinfSynthesis, SearchedControllerMeetsTheGammaItReports) {
  const HinfController k = hinf_synthesis(sb10fd_example(), 2, 2);
  EXPECT_GT(k.gamma_min, 0.0);
  EXPECT_LT(k.gamma_min, 15.0);  // the published suboptimal level is not the least
  EXPECT_DOUBLE_EQ(k.gamma, 1.01 * k.gamma_min);
  EXPECT_LT(max_real_pole(k.closed_loop.A), 0.0);
  const double norm = hinf_norm(k.closed_loop, TimeDomain::Continuous).norm;
  EXPECT_LE(norm, k.gamma * (1 + 1e-6));
  EXPECT_GT(norm, 0.9 * k.gamma_min);  // near optimal, not just stabilizing
}

TEST(HinfNorm, FindsThePeakOfSlicotsExample) {
  StateSpace s{Eigen::MatrixXd::Zero(6, 6), Eigen::MatrixXd::Zero(6, 1), Eigen::MatrixXd::Zero(1, 6),
               Eigen::MatrixXd::Zero(1, 1)};
  const double k[3] = {0.5, 1.0, 2.0}, c[3] = {0.0002, 0.00002, 0.000002};
  for (int i = 0; i < 3; ++i) {
    s.A(2 * i, 2 * i + 1) = 1.0;
    s.A(2 * i + 1, 2 * i) = -k[i];
    s.A(2 * i + 1, 2 * i + 1) = -c[i];
    s.B(2 * i, 0) = 1.0;
    s.C(0, 2 * i) = 1.0;
  }
  const HinfNorm h = hinf_norm(s, TimeDomain::Continuous);
  EXPECT_NEAR(h.norm, 0.5000000001e6, 1e-3);
  EXPECT_NEAR(h.frequency, std::sqrt(2.0), 1e-9);
}

TEST(HinfNorm, FirstOrderLagPeaksAtZeroFrequency) {
  const StateSpace lag{Eigen::MatrixXd::Constant(1, 1, -2.0), Eigen::MatrixXd::Constant(1, 1, 3.0),
                       Eigen::MatrixXd::Constant(1, 1, 1.0), Eigen::MatrixXd::Zero(1, 1)};
  EXPECT_NEAR(hinf_norm(lag, TimeDomain::Continuous).norm, 1.5, 1e-9);  // 3/(s+2) at s = 0
}

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(HinfSynthesis, IllPosedPlantsAreNamedNotCrashed) {
  StateSpace p = sb10fd_example();
  p.D.block(0, 3, 3, 2).setZero();  // D12 = 0: the control reaches no performance output directly
  const std::string d12 = message_of([&] { hinf_synthesis(p, 2, 2); });
  EXPECT_NE(d12.find("D12 does not have full column rank"), std::string::npos) << d12;
  p = sb10fd_example();
  p.D.block(3, 0, 2, 3).setZero();  // D21 = 0: no sensor noise
  const std::string d21 = message_of([&] { hinf_synthesis(p, 2, 2); });
  EXPECT_NE(d21.find("D21 does not have full row rank"), std::string::npos) << d21;
  EXPECT_NE(message_of([&] { hinf_synthesis(sb10fd_example(), 4, 2); }).find("nmeas <= disturbances"),
            std::string::npos);
  // An unstable mode (A(0,0) = 5, decoupled) that neither u nor y touches.
  p = sb10fd_example();
  p.A.row(0).setZero();
  p.A.col(0).setZero();
  p.A(0, 0) = 5.0;
  p.B.row(0).setZero();
  p.C.col(0).setZero();
  const std::string unstabilizable = message_of([&] { hinf_synthesis(p, 2, 2); });
  EXPECT_NE(unstabilizable.find("(A, B2) is not stabilizable"), std::string::npos) << unstabilizable;
  EXPECT_NE(unstabilizable.find("mode at 5"), std::string::npos) << unstabilizable;
  HinfOptions tight;
  tight.fixed_gamma = 0.1;
  EXPECT_NE(message_of([&] { hinf_synthesis(sb10fd_example(), 2, 2, tight); }).find("gamma too small"),
            std::string::npos);
}

TEST(HinfNorm, UnstableSystemHasAnInfiniteNorm) {
  const StateSpace unstable{Eigen::MatrixXd::Constant(1, 1, 2.0), Eigen::MatrixXd::Ones(1, 1),
                            Eigen::MatrixXd::Ones(1, 1), Eigen::MatrixXd::Zero(1, 1)};
  EXPECT_TRUE(std::isinf(hinf_norm(unstable, TimeDomain::Continuous).norm));
  EXPECT_TRUE(std::isinf(hinf_norm(unstable, TimeDomain::Discrete).norm));  // |2| > 1 too
}

TEST(HinfNorm, BadArgumentComesBackAsAMessageNotAnExit) {
  const StateSpace lag{Eigen::MatrixXd::Constant(1, 1, -2.0), Eigen::MatrixXd::Constant(1, 1, 3.0),
                       Eigen::MatrixXd::Constant(1, 1, 1.0), Eigen::MatrixXd::Zero(1, 1)};
  // TOL must lie in [0, 1): LAPACK-style XERBLA would stop the process.
  EXPECT_NE(message_of([&] { hinf_norm(lag, TimeDomain::Continuous, 2.0); }).find("AB13DD: argument 20 is invalid"),
            std::string::npos);
}

}  // namespace
}  // namespace hystbench::robust
