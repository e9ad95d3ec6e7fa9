#include "framework/model/held_start.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>

#include "framework/model/model.hpp"

namespace hystbench {

ModelData with_held_input(const ModelData& data, double level, Eigen::Index samples) {
  const Eigen::Index n = data.u.size();
  ModelData e = data;
  e.held_start = false;
  e.warmup = data.warmup + samples;
  e.u.resize(samples + n);
  e.u << Eigen::VectorXd::Constant(samples, level), data.u;
  e.y.resize(samples + n);
  e.y << Eigen::VectorXd::Zero(samples), data.y;
  e.estimation.resize(samples + n);
  e.estimation << Eigen::VectorXd::Zero(samples), data.estimation;
  if (data.t.size() == n) {
    e.t.resize(samples + n);
    e.t << Eigen::VectorXd::LinSpaced(samples, -double(samples), -1.0) * data.sample_time, data.t;
  }
  if (!data.segment.empty()) {
    e.segment.assign(std::size_t(samples), data.segment.front());
    e.segment.insert(e.segment.end(), data.segment.begin(), data.segment.end());
  }
  return e;
}

namespace {

// Mean model output minus mean measured output over the warm-up, with the
// input held at `level` before the record; NaN when the model diverges.
struct WarmupMismatch {
  const Model& model;
  const Eigen::Ref<const Eigen::VectorXd>& x;
  ModelData warmup;  // the warm-up samples alone
  double measured;

  double operator()(double level) const {
    const ModelData e = with_held_input(warmup, level, kHeldStartSamples);
    Eigen::VectorXd y;
    if (!model.simulate(x, e, y)) return std::nan("");
    return y.tail(warmup.size()).mean() - measured;
  }
};

}  // namespace

bool held_level(const Model& model, const Eigen::Ref<const Eigen::VectorXd>& x, const ModelData& data,
                double& level) {
  // with_held_input starts its copy at rest: no recursion into held_level.
  const ModelData head = data.head(std::max<Eigen::Index>(data.warmup, 1));
  const WarmupMismatch g{model, x, head, head.y.mean()};
  const double low = data.u.minCoeff(), high = data.u.maxCoeff();
  // A constant input still gets a range: u is scaled to unit RMS.
  const double span = high > low ? high - low : 1.0;
  // An end where the model diverges (a jump from rest to a level far beyond
  // the record's range) moves in: to the record's own range, then to its middle.
  const auto finite_end = [&](std::initializer_list<double> tries, double& at, double& value) {
    for (double t : tries) {
      value = g(t);
      if (std::isfinite(value)) {
        at = t;
        return true;
      }
    }
    return false;
  };
  double a = 0, ga = 0, b = 0, gb = 0;
  const double middle = 0.5 * (low + high);
  if (!finite_end({low - 0.5 * span, low, middle}, a, ga) || !finite_end({high + 0.5 * span, high, middle}, b, gb))
    return false;
  if (ga == 0.0 || gb == 0.0 || ga * gb > 0) {  // a match at an end, or none inside: the nearer end
    level = std::abs(ga) <= std::abs(gb) ? a : b;
    return true;
  }
  // Illinois regula falsi: the mismatch is close to linear in the level
  // wherever the chain is, so a few steps reach rounding.
  for (int i = 0; i < 60 && std::abs(b - a) > 1e-12 * (1.0 + span); ++i) {
    const double c = (a * gb - b * ga) / (gb - ga);
    const double gc = g(c);
    if (!std::isfinite(gc)) return false;
    if (gc * gb < 0)
      a = b, ga = gb;
    else
      ga /= 2;  // `a` kept twice: halve its weight so that it moves
    b = c, gb = gc;
    if (std::abs(gc) <= 1e-12 * (1.0 + std::abs(g.measured))) break;
  }
  level = b;
  return true;
}

}  // namespace hystbench
