#pragma once
// The 13-parameter Hammerstein seed model of an MFC actuator
// (docs/models.md#hammerstein-seed-model):
// Bouc-Wen hysteresis -> asymmetric static part -> mass-spring-damper
// (bilinear discretisation) -> second-order ARX.
//
// Initial state: the system is at rest with zero input before the first
// sample (u[-1] = 0 and every internal signal at k < 0 is 0).
#include "framework/core/eigen.hpp"
#include <array>
#include <string>
#include <vector>

namespace hystbench {

enum class BoucWenForm {
  Increment,  // h driven by du = u[k] - u[k-1]: the discretised Bouc-Wen ODE (default)
  Paper,      // h driven by u[k] itself, as printed in the MEDE paper; see docs/models.md
};

std::string to_string(BoucWenForm form);
BoucWenForm bouc_wen_form_from_string(const std::string& text);  // "increment" | "paper"

struct HammersteinParams {
  double alpha, beta, gamma, L;  // Bouc-Wen (alpha and L enter only as alpha*L)
  double d1, d2;                 // static part d1 u + d2 u^2
  double M, D, K;                // mass, damping, stiffness
  double a, b, c, d;             // ARX: r1[k] = a r[k-1] + b r[k-2] - c r1[k-1] - d r1[k-2]

  static constexpr int kCount = 13;
  static const std::array<std::string, kCount>& names();
  static HammersteinParams from_vector(const Eigen::Ref<const Eigen::VectorXd>& x);
  Eigen::VectorXd to_vector() const;
};

// True when both linear blocks are asymptotically stable (Jury test on their
// second-order denominators). Unstable parameter sets have fitness +inf.
bool linear_blocks_stable(const HammersteinParams& p, double Ts);

// Model output y_hat for input u at sample time Ts. Non-finite values mean
// the simulation diverged.
Eigen::VectorXd simulate_hammerstein(const HammersteinParams& p, const Eigen::VectorXd& u,
                                     double Ts, BoucWenForm form);

// Sum of squared errors against y; +inf when unstable or divergent.
double hammerstein_sse(const HammersteinParams& p, const Eigen::VectorXd& u,
                       const Eigen::VectorXd& y, double Ts, BoucWenForm form);

}  // namespace hystbench
