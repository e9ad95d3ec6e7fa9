#include "framework/model/spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <unsupported/Eigen/FFT>

namespace hystbench {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kShortestSegment = 8;

std::vector<double> hann(int length) {
  std::vector<double> w(std::size_t(length), 0.0);
  for (int k = 0; k < length; ++k) w[std::size_t(k)] = 0.5 - 0.5 * std::cos(2 * kPi * k / length);
  return w;
}

}  // namespace

Spectrum welch_spectrum(const Eigen::VectorXd& x, double sample_time, int length) {
  Spectrum s;
  length = int(std::min<Eigen::Index>(length, x.size()));
  if (length < kShortestSegment || !(sample_time > 0)) return s;
  const std::vector<double> window = hann(length);
  const int bins = length / 2 + 1;
  s.power.assign(std::size_t(bins), 0.0);
  for (int b = 0; b < bins; ++b) s.frequency.push_back(b / (length * sample_time));
  Eigen::FFT<double> fft;
  std::vector<double> segment(static_cast<std::size_t>(length));
  std::vector<std::complex<double>> transform;
  int segments = 0;
  for (Eigen::Index start = 0; start + length <= x.size(); start += length / 2, ++segments) {
    const double mean = x.segment(start, length).mean();
    for (int k = 0; k < length; ++k)
      segment[std::size_t(k)] = (x[start + k] - mean) * window[std::size_t(k)];
    fft.fwd(transform, segment);
    for (int b = 0; b < bins; ++b) s.power[std::size_t(b)] += std::norm(transform[std::size_t(b)]);
  }
  for (double& p : s.power) p /= segments;
  return s;
}

}  // namespace hystbench
