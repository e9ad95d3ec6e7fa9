#pragma once
// A linear time-invariant system in state-space form, x' = A x + B u,
// y = C x + D u (continuous) or x(k+1) = A x(k) + B u(k), y = C x + D u
// (discrete), the type every robust-control routine here takes and returns.
// Matrices are Eigen's (column-major, as Fortran expects them).
#include "framework/core/eigen.hpp"

#include "framework/core/error.hpp"

namespace hystbench::robust {

struct StateSpace {
  Eigen::MatrixXd A, B, C, D;

  Eigen::Index states() const { return A.rows(); }
  Eigen::Index inputs() const { return B.cols(); }
  Eigen::Index outputs() const { return C.rows(); }
  // Whether the sizes agree: A n×n, B n×m, C p×n, D p×m.
  bool consistent() const {
    return A.rows() == A.cols() && B.rows() == A.rows() && C.cols() == A.rows() && D.rows() == C.rows() &&
           D.cols() == B.cols();
  }
};

// a − b for systems of the same inputs and outputs: the states side by side.
inline StateSpace difference(const StateSpace& a, const StateSpace& b) {
  if (!a.consistent() || !b.consistent() || a.inputs() != b.inputs() || a.outputs() != b.outputs())
    throw InputError("difference: the systems must have consistent matrices and the same inputs and outputs");
  const Eigen::Index na = a.states(), nb = b.states();
  StateSpace d{Eigen::MatrixXd::Zero(na + nb, na + nb), Eigen::MatrixXd(na + nb, a.inputs()),
               Eigen::MatrixXd(a.outputs(), na + nb), a.D - b.D};
  d.A.topLeftCorner(na, na) = a.A;
  d.A.bottomRightCorner(nb, nb) = b.A;
  d.B << a.B, b.B;
  d.C << a.C, -b.C;
  return d;
}

}  // namespace hystbench::robust
