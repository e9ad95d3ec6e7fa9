#include "framework/tracking/tracking_loop.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "framework/core/rng.hpp"
#include "framework/robust/discrete_stream.hpp"

namespace hystbench {
namespace {

// The feedback law of one controller, e -> w*.
class Feedback {
 public:
  Feedback(const TrackingController& c, double sample_time) : c_(c), ts_(sample_time) {
    if (c.kind == TrackingController::Kind::Hinf) stream_ = std::make_unique<robust::DiscreteStream>(c.feedback);
  }
  double step(double e, bool saturated) {
    switch (c_.kind) {
      case TrackingController::Kind::Hinf: return stream_->step(e);
      case TrackingController::Kind::Pi:
        if (!saturated) integral_ += e * ts_;  // no windup while the actuator cannot follow
        return c_.kp * e + c_.ki * integral_;
      default: return 0.0;
    }
  }

 private:
  const TrackingController& c_;
  double ts_;
  std::unique_ptr<robust::DiscreteStream> stream_;
  double integral_ = 0.0;
};

double sensed(double y, const SensorSettings& s, Rng& rng) {
  if (s.noise_sd > 0.0) y += s.noise_sd * rng.normal();
  return s.resolution > 0.0 ? s.resolution * std::round(y / s.resolution) : y;
}

double fade_in(double t, double length) {
  return t >= length ? 1.0 : 0.5 - 0.5 * std::cos(std::numbers::pi * t / length);
}

}  // namespace

TrackingRun run_tracking(const TrackingSetup& setup, const TrackingController& controller,
                         const TrackingReference& reference, const ScoreWindow& window, std::uint64_t seed) {
  TrackingRun run;
  run.window = window_samples(reference, window, setup.sample_time);
  const Eigen::Index n = run.window.end();
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  run.r.setConstant(n, kNaN), run.y.setConstant(n, kNaN), run.u.setConstant(n, kNaN);
  auto plant = setup.plant->clone();
  InverseCompensator inverse(*setup.inverse);
  inverse.reset();
  robust::DiscreteStream feedforward(*setup.feedforward);
  Feedback feedback(controller, setup.sample_time);
  Rng rng(seed);
  const bool use_wr = controller.kind != TrackingController::Kind::Pi;
  double u = 0.0;
  long saturated_before = 0;
  const double fade = std::min(0.1, double(run.window.begin) * setup.sample_time / 2);  // within the settling
  long saturated_at_window = 0;
  for (Eigen::Index k = 0; k < n; ++k) {
    const double t = double(k) * setup.sample_time;
    const double r = reference.value(t) * fade_in(t, fade);
    if (k == run.window.begin) saturated_at_window = inverse.statistics().saturated;
    const double y = sensed(plant->step(u), setup.sensor, rng);
    const double ff = use_wr ? feedforward.step(r) : r;
    const bool saturated = inverse.statistics().saturated > saturated_before;
    saturated_before = inverse.statistics().saturated;
    const double w = ff + feedback.step(r - y, saturated);
    // A controller whose state overflowed: the amplifier would keep y
    // finite, so the run is stopped and marked rather than scored.
    if (!std::isfinite(w) || !std::isfinite(y)) {
      run.finite = false;
      break;
    }
    u = inverse.step(w);
    run.r[k] = r, run.y[k] = y, run.u[k] = u;
  }
  run.inverse = inverse.statistics();
  run.saturated_in_window = run.inverse.saturated - saturated_at_window;
  run.score = run.finite ? score_tracking(run.r, run.y, run.window, reference.offset)
                         : TrackingScore{kNaN, kNaN, kNaN, kNaN};
  return run;
}

}  // namespace hystbench
