#include "framework/model/held_start.hpp"

#include <cmath>

#include "framework/model/model.hpp"

namespace hystbench {

ModelData with_held_input(const ModelData& data, double level, Eigen::Index samples) {
  const Eigen::Index n = data.size();
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
  ModelData head = data.head(std::max<Eigen::Index>(data.warmup, 1));
  head.held_start = false;
  head.warmup = 0;
  const WarmupMismatch g{model, x, head, head.y.mean()};
  const double span = data.u.maxCoeff() - data.u.minCoeff();
  double a = data.u.minCoeff() - 0.5 * span, b = data.u.maxCoeff() + 0.5 * span;
  double ga = g(a), gb = g(b);
  if (!std::isfinite(ga) || !std::isfinite(gb)) return false;
  if (ga * gb > 0) {  // no match inside: the nearer end
    level = std::abs(ga) < std::abs(gb) ? a : b;
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
