#include "framework/discovery/resonance.hpp"

#include <cmath>
#include <complex>
#include <cstdio>

namespace hystbench {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kImpulse = 1e-3;  // small: the linearised response of a nonlinear block
constexpr int kGridPoints = 240;
constexpr double kSameMode = 0.10;  // relative frequency difference

// Impulse response of `effect` alone (gain 1), `n` samples.
bool impulse_response(const Model& model, const Eigen::VectorXd& x, const std::string& effect,
                      double ts, Eigen::Index n, Eigen::VectorXd& h) {
  const Model alone({effect});
  Eigen::VectorXd p = alone.carry_over(model, x);
  p[0] = 1.0;
  Measurement m;
  m.sample_time = ts;
  m.t = Eigen::VectorXd::LinSpaced(n, 0.0, ts * double(n - 1));
  m.u = Eigen::VectorXd::Zero(n);
  m.u[0] = kImpulse;
  m.y = Eigen::VectorXd::Zero(n);
  if (!alone.simulate(p, ModelData(m, {}), h)) return false;
  h /= kImpulse;
  return true;
}

double gain_at(const Eigen::VectorXd& h, double hz, double ts) {
  std::complex<double> sum = 0;
  const double w = 2 * kPi * hz * ts;
  for (Eigen::Index k = 0; k < h.size(); ++k) sum += h[k] * std::polar(1.0, -w * double(k));
  return std::abs(sum);
}

}  // namespace

std::vector<Resonance> resonances(const Model& model, const Eigen::VectorXd& x, double ts) {
  std::vector<Resonance> out;
  const auto& registry = EffectRegistry::instance();
  const Eigen::Index n = std::max<Eigen::Index>(1024, Eigen::Index(std::ceil(4.0 / ts)));
  const double low = 1.0 / (double(n) * ts), high = 0.45 / ts;
  for (const auto& effect : model.effects()) {
    if (registry.find(effect, "effect").stage != EffectStage::Dynamics) continue;
    Eigen::VectorXd h;
    if (!impulse_response(model, x, effect, ts, n, h) || !h.allFinite()) continue;
    Resonance r{effect};
    const double base = gain_at(h, low, ts);
    const double step = std::pow(high / low, 1.0 / (kGridPoints - 1));
    for (int i = 0; i < kGridPoints; ++i) {
      const double hz = low * std::pow(step, double(i));
      const double g = gain_at(h, hz, ts);
      if (g > r.peak_gain) r.peak_gain = g, r.hz = hz;
    }
    // Then finely between the grid neighbours of the peak.
    const double from = r.hz / step, to = r.hz * step;
    for (int i = 0; i <= kGridPoints / 4; ++i) {
      const double hz = from + (to - from) * double(i) / (kGridPoints / 4);
      const double g = gain_at(h, hz, ts);
      if (g > r.peak_gain) r.peak_gain = g, r.hz = hz;
    }
    r.peak_gain /= base;
    if (base > 0 && r.peak_gain >= 1.2) out.push_back(r);
  }
  return out;
}

std::string shared_resonance(const Model& model, const Eigen::VectorXd& x, double ts,
                             const std::string& effect) {
  const auto all = resonances(model, x, ts);
  const Resonance* mine = nullptr;
  for (const auto& r : all)
    if (r.effect == effect) mine = &r;
  if (!mine) return "";
  for (const auto& r : all) {
    if (r.effect == effect || std::abs(r.hz - mine->hz) > kSameMode * r.hz) continue;
    char buf[256];
    std::snprintf(buf, sizeof buf,
                  "%s resonates at %.3g Hz, as %s does (%.3g Hz): it describes the same mode "
                  "again rather than a new one",
                  effect.c_str(), mine->hz, r.effect.c_str(), r.hz);
    return buf;
  }
  return "";
}

}  // namespace hystbench
