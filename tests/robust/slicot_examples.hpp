#pragma once
// The example systems of SLICOT's documentation, which the tests and the
// benchmark of framework/robust/ use: their published results are the
// reference.
#include <initializer_list>

#include "framework/robust/state_space.hpp"

namespace hystbench::robust::examples {

// An r×c matrix from its entries row by row, as the documentation lists them.
inline Eigen::MatrixXd rows(int r, int c, std::initializer_list<double> v) {
  Eigen::MatrixXd m(r, c);
  auto it = v.begin();
  for (int i = 0; i < r; ++i)
    for (int j = 0; j < c; ++j) m(i, j) = *it++;
  return m;
}

// SB10FD's generalized plant: 6 states, w, u = 3 + 2 inputs, z, y = 3 + 2 outputs.
inline StateSpace sb10fd_plant() {
  return {rows(6, 6, {-1, 0, 4, 5, -3, -2, -2, 4, -7, -2, 0, 3, -6, 9, -5, 0, 2, -1,
                      -8, 4, 7, -1, -3, 0, 2, 5, 8, -9, 1, -4, 3, -5, 8, 0, 2, -6}),
          rows(6, 5, {-3, -4, -2, 1, 0, 2, 0, 1, -5, 2, -5, -7, 0, 7, -2,
                      4, -6, 1, 1, -2, -3, 9, -8, 0, 5, 1, -2, 3, -6, -2}),
          rows(5, 6, {1, -1, 2, -4, 0, -3, -3, 0, 5, -1, 1, 1, -7, 5, 0, -8, 2, -2,
                      9, -3, 4, 0, 3, 7, 0, 1, -2, 1, -6, -2}),
          rows(5, 5, {1, -2, -3, 0, 0, 0, 4, 0, 1, 0, 5, -3, -4, 0, 1, 0, 1, 0, 1, -3, 0, 0, 1, 7, 1})};
}

// AB09AD's and AB09HD's 7-state system, 2 inputs, 3 outputs.
inline StateSpace ab09_system() {
  return {rows(7, 7, {-0.04165, 0, 4.92, -4.92, 0, 0, 0, -5.21, -12.5, 0, 0, 0, 0, 0, 0, 3.33, -3.33, 0, 0, 0, 0,
                      0.545, 0, 0, 0, -0.545, 0, 0, 0, 0, 0, 4.92, -0.04165, 0, 4.92, 0, 0, 0, 0, -5.21, -12.5, 0,
                      0, 0, 0, 0, 0, 3.33, -3.33}),
          rows(7, 2, {0, 0, 12.5, 0, 0, 0, 0, 0, 0, 0, 0, 12.5, 0, 0}),
          rows(3, 7, {1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0}), Eigen::MatrixXd::Zero(3, 2)};
}

}  // namespace hystbench::robust::examples
