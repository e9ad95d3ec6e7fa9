#pragma once
// Fixed-order H∞ tuning as an optimization problem (docs/tracking.md#fixed-order):
// the decision variables shape a controller of fixed order n (3 by default),
//
//   K(s) = k · Z(s) / P(s),  P of degree n, Z of degree n − 1 (strictly proper),
//
// with the roots of P and Z taken two at a time as pairs s² + 2ζω s + ω²
// (log10 ω and ζ; ζ > 1 gives two real roots) and a last odd one as a real
// root s + ω (log10 ω), and log10 k the gain. The fitness is the H∞ norm
// of the closed loop lft(P_gen, K) (SLICOT's AB13DD); a loop K does not
// stabilise costs 1e6 plus its largest real pole part, so a search is
// drawn towards stability. This is MATLAB's hinfstruct/systune job done by
// any optimizer plugin, against synthesis then reduction. A stable loop
// whose norm exceeds the penalty is possible in principle (a huge gain on
// a poorly damped pair); none is in reach of the default bounds' search.
//
// Experiment file:
//   "problem": {"type": "fixed_order_hinf", "order": 3,
//               "experiment": "tracking.json" (optional: the generalized plant of a
//               tracking experiment's design; without it, the reference design of
//               the tests: L = 1260 Hz, damping 0.6, seed 002's Wa, Wp at 100 Hz),
//               "log10_gain": [0, 6], "log10_omega": [-3, 5], "zeta": [0.05, 2]}
// describe() gives the norm of the synthesise-then-reduce controller of the
// same order on the same plant: the value to beat.
#include <filesystem>
#include <string>
#include <nlohmann/json.hpp>

#include "framework/core/problem.hpp"
#include "framework/core/registry.hpp"
#include "framework/robust/state_space.hpp"

namespace hystbench {

class FixedOrderHinfProblem : public Problem {
 public:
  static ProblemInfo info();
  FixedOrderHinfProblem(const Params& options, const std::filesystem::path& base_dir);

  std::string name() const override;
  const Bounds& bounds() const override { return bounds_; }
  void evaluate(const Eigen::Ref<const Eigen::MatrixXd>& X, Eigen::Ref<Eigen::VectorXd> f) const override;
  nlohmann::json describe() const override;

  // The controller a decision vector stands for.
  robust::StateSpace controller(const Eigen::Ref<const Eigen::VectorXd>& x) const;
  double fitness(const Eigen::Ref<const Eigen::VectorXd>& x) const;
  const robust::StateSpace& plant() const { return plant_; }

 private:
  robust::StateSpace plant_;  // generalized plant [w; u] -> [z; e]
  int order_ = 3;
  Bounds bounds_;
  std::string source_;
  double reference_norm_ = 0.0;  // synthesis then reduction to the same order
  std::string reference_method_;
};

// Referring to it keeps the problem's registration in a program linked with
// the static robust library (the linker drops unreferenced objects).
void link_fixed_order_hinf();

}  // namespace hystbench
