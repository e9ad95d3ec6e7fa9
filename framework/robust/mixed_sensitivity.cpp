#include "framework/robust/mixed_sensitivity.hpp"

#include "framework/core/error.hpp"

namespace hystbench::robust {
namespace {

void check(const StateSpace& w, Eigen::Index size, const char* name) {
  if (!w.consistent() || w.inputs() != size)
    throw InputError(std::string("mixed_sensitivity_plant: the weight ") + name + " must take " +
                     std::to_string(size) + " inputs and have consistent matrices");
}

}  // namespace

StateSpace mixed_sensitivity_plant(const StateSpace& G, const SensitivityWeights& w) {
  if (!G.consistent()) throw InputError("mixed_sensitivity_plant: the plant's matrices have inconsistent sizes");
  const Eigen::Index p = G.outputs(), m = G.inputs();
  if (w.on_error) check(*w.on_error, p, "on the error (W1)");
  if (w.on_control) check(*w.on_control, m, "on the control (W2)");
  if (w.on_output) check(*w.on_output, p, "on the output (W3)");
  if (!w.on_error && !w.on_control && !w.on_output)
    throw InputError("mixed_sensitivity_plant: give at least one weight");
  const StateSpace none{Eigen::MatrixXd(0, 0), Eigen::MatrixXd(0, p), Eigen::MatrixXd(0, 0), Eigen::MatrixXd(0, p)};
  const StateSpace& W1 = w.on_error ? *w.on_error : none;
  const StateSpace none_u{Eigen::MatrixXd(0, 0), Eigen::MatrixXd(0, m), Eigen::MatrixXd(0, 0), Eigen::MatrixXd(0, m)};
  const StateSpace& W2 = w.on_control ? *w.on_control : none_u;
  const StateSpace& W3 = w.on_output ? *w.on_output : none;
  const Eigen::Index ng = G.states(), n1 = W1.states(), n2 = W2.states(), n3 = W3.states();
  const Eigen::Index n = ng + n1 + n2 + n3, z1 = W1.outputs(), z2 = W2.outputs(), z3 = W3.outputs();
  const Eigen::Index o1 = ng, o2 = ng + n1, o3 = ng + n1 + n2;  // state offsets
  StateSpace P{Eigen::MatrixXd::Zero(n, n), Eigen::MatrixXd::Zero(n, p + m),
               Eigen::MatrixXd::Zero(z1 + z2 + z3 + p, n), Eigen::MatrixXd::Zero(z1 + z2 + z3 + p, p + m)};
  // States: G driven by u; W1 by e = w − G u; W2 by u; W3 by G u.
  P.A.topLeftCorner(ng, ng) = G.A;
  P.B.block(0, p, ng, m) = G.B;
  P.A.block(o1, 0, n1, ng) = -W1.B * G.C;
  P.A.block(o1, o1, n1, n1) = W1.A;
  P.B.block(o1, 0, n1, p) = W1.B;
  P.B.block(o1, p, n1, m) = -W1.B * G.D;
  P.A.block(o2, o2, n2, n2) = W2.A;
  P.B.block(o2, p, n2, m) = W2.B;
  P.A.block(o3, 0, n3, ng) = W3.B * G.C;
  P.A.block(o3, o3, n3, n3) = W3.A;
  P.B.block(o3, p, n3, m) = W3.B * G.D;
  // Outputs z1, z2, z3, then v = e.
  P.C.block(0, 0, z1, ng) = -W1.D * G.C;
  P.C.block(0, o1, z1, n1) = W1.C;
  P.D.block(0, 0, z1, p) = W1.D;
  P.D.block(0, p, z1, m) = -W1.D * G.D;
  P.C.block(z1, o2, z2, n2) = W2.C;
  P.D.block(z1, p, z2, m) = W2.D;
  P.C.block(z1 + z2, 0, z3, ng) = W3.D * G.C;
  P.C.block(z1 + z2, o3, z3, n3) = W3.C;
  P.D.block(z1 + z2, p, z3, m) = W3.D * G.D;
  P.C.block(z1 + z2 + z3, 0, p, ng) = -G.C;
  P.D.block(z1 + z2 + z3, 0, p, p) = Eigen::MatrixXd::Identity(p, p);
  P.D.block(z1 + z2 + z3, p, p, m) = -G.D;
  return P;
}

}  // namespace hystbench::robust
