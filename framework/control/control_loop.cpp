#include "framework/control/control_loop.hpp"

#include <cmath>
#include <limits>

#include "framework/core/rng.hpp"

namespace hystbench {
namespace {

// Watches the 1 s moving mean square of the true error, updated by adding
// the new sample's square and removing the one a window ago.
class DivergenceWatch {
 public:
  DivergenceWatch(double level, long window)
      : limit_(level * level), window_(window), squares_(window, 0.0) {}
  bool diverged(double true_error, double u) {
    if (!std::isfinite(true_error) || !std::isfinite(u)) return true;
    if (limit_ <= 0.0) return false;
    const std::size_t slot = static_cast<std::size_t>(n_++ % window_);
    sum_ += true_error * true_error - squares_[slot];
    squares_[slot] = true_error * true_error;
    return sum_ / double(window_) > limit_;
  }

 private:
  double limit_;
  long window_;
  std::vector<double> squares_;
  double sum_ = 0.0;
  long n_ = 0;
};

// Start of the final stretch in which the 1 s moving RMS stays above
// `level`, when the run ends inside one; NaN otherwise.
double unsettled_since(const std::vector<double>& true_error, double level, double fs) {
  const auto rms = moving_rms(true_error, std::lround(fs));
  if (level <= 0.0 || rms.empty() || !(rms.back() > level)) return std::nan("");
  std::size_t n = rms.size() - 1;
  while (n > 0 && rms[n - 1] > level) --n;
  return double(n) / fs;
}

}  // namespace

long LoopSettings::samples() const { return std::lround(duration_s * sample_rate_hz); }

bool LoopTrace::diverged() const { return !std::isnan(diverged_at_s); }

LoopTrace run_loop(const LoopPaths& paths, const SignalStream& estimate_path,
                   Controller& controller, const LoopSettings& s, std::uint64_t noise_seed) {
  auto control = paths.control->clone();
  auto disturbance = paths.disturbance->clone();
  auto estimate = estimate_path.clone();
  control->reset();
  disturbance->reset();
  estimate->reset();
  controller.reset();
  Rng noise(noise_seed);
  const long n_samples = s.samples();
  const double w = 2.0 * M_PI * s.disturbance_hz / s.sample_rate_hz;
  DivergenceWatch watch(s.divergence_level, std::lround(s.sample_rate_hz));
  LoopTrace t;
  for (auto* v : {&t.error, &t.true_error, &t.control, &t.step, &t.weight_norm})
    v->reserve(n_samples);
  for (long n = 0; n < n_samples; ++n) {
    const double phase = std::sin(w * double(n));
    const double x = s.reference_amplitude * phase;
    const double u = controller.output(x);
    const double e_true = disturbance->step(s.disturbance_amplitude * phase) + control->step(u);
    const double e = e_true + s.noise_sd * noise.normal();
    controller.adapt(e, estimate->step(x));
    t.error.push_back(e);
    t.true_error.push_back(e_true);
    t.control.push_back(u);
    t.step.push_back(controller.step_size());
    t.weight_norm.push_back(controller.weight_norm());
    if (watch.diverged(e_true, u) || !std::isfinite(t.weight_norm.back())) {
      t.diverged_at_s = double(n) / s.sample_rate_hz;
      return t;
    }
  }
  t.diverged_at_s = unsettled_since(t.true_error, LoopSettings::kUnsettledRatio * s.uncontrolled_level,
                                    s.sample_rate_hz);
  return t;
}

std::vector<double> moving_rms(const std::vector<double>& x, long window) {
  std::vector<double> out(x.size());
  double sum = 0.0;
  for (std::size_t n = 0; n < x.size(); ++n) {
    sum += x[n] * x[n];
    if (n >= static_cast<std::size_t>(window)) sum -= x[n - window] * x[n - window];
    const double count = double(std::min<std::size_t>(n + 1, window));
    out[n] = std::sqrt(std::max(sum, 0.0) / count);
  }
  return out;
}

}  // namespace hystbench
