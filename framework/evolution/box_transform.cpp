#include "framework/evolution/box_transform.hpp"

#include <algorithm>
#include <cmath>

namespace hystbench {
namespace {

double margin(double l, double u, double bound) {
  return std::min((u - l) / 2, 0.05 * std::max(std::abs(bound), 1.0));
}

// The fold and the mirror of docs/algorithms.md#boundtransform: bring y into
// [l - a_l, u + a_u], where the quadratic pieces are invertible.
double fold_into_window(double y, double l, double u, double al, double au) {
  const double width = u - l;
  const double start = l - 2 * al - width / 2;
  if (y < start || y > u + 2 * au + width / 2) {
    const double period = 2 * (width + al + au);
    y -= period * std::floor((y - start) / period);
  }
  if (y > u + au) y -= 2 * (y - u - au);
  if (y < l - al) y += 2 * (l - al - y);
  return y;
}

}  // namespace

double box_transform(double y, double l, double u) {
  if (!(u > l)) return l;
  const double al = margin(l, u, l);
  const double au = margin(l, u, u);
  y = fold_into_window(y, l, u, al, au);
  if (y < l + al) y = l + (y - (l - al)) * (y - (l - al)) / (4 * al);
  else if (y > u - au) y = u - (y - (u + au)) * (y - (u + au)) / (4 * au);
  return std::clamp(y, l, u);  // rounding only
}

Eigen::VectorXd unit_box_transform(const Eigen::Ref<const Eigen::VectorXd>& y) {
  Eigen::VectorXd z(y.size());
  for (Eigen::Index j = 0; j < y.size(); ++j) z[j] = box_transform(y[j], 0.0, 1.0);
  return z;
}

}  // namespace hystbench
