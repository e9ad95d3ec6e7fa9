#include "framework/model/model_data.hpp"

#include <algorithm>
#include <cmath>

#include "framework/core/error.hpp"

namespace hystbench {
namespace {

double rms_or_one(const Eigen::VectorXd& v) {
  const double r = v.size() ? std::sqrt(v.squaredNorm() / double(v.size())) : 0.0;
  return r > 0.0 && std::isfinite(r) ? r : 1.0;
}

}  // namespace

SignalScales SignalScales::of(const Measurement& m) { return {rms_or_one(m.u), rms_or_one(m.y)}; }

SignalScales SignalScales::from_json(const nlohmann::json& j, const std::string& where) {
  SignalScales s;
  try {
    s.u = j.at("u").get<double>();
    s.y = j.at("y").get<double>();
  } catch (const nlohmann::json::exception&) {
    throw InputError(where + ": expected {\"u\": number, \"y\": number}");
  }
  if (!(s.u > 0.0) || !(s.y > 0.0)) throw InputError(where + ": scales must be positive");
  return s;
}

nlohmann::json SignalScales::to_json() const { return {{"u", u}, {"y", y}}; }

ModelData::ModelData(const Measurement& m, SignalScales s)
    : t(m.t.array() - m.t[0]),
      u(m.u / s.u),
      y(m.y / s.y),
      sample_time(m.sample_time),
      scales(s),
      segment(m.segment),
      estimation(Eigen::VectorXd::Ones(m.size())) {}

ModelData ModelData::head(Eigen::Index n) const {
  ModelData h = *this;
  h.t = t.head(n);
  h.u = u.head(n);
  h.y = y.head(n);
  h.estimation = estimation.head(n);
  h.warmup = std::min(warmup, n);
  if (!segment.empty()) h.segment.assign(segment.begin(), segment.begin() + n);
  return h;
}

Eigen::VectorXd ModelData::heldout_mask() const {
  Eigen::VectorXd held = (1.0 - estimation.array()).matrix();
  held.head(warmup).setZero();
  return held;
}

Eigen::Index ModelData::estimation_count() const {
  return static_cast<Eigen::Index>(estimation.sum());
}

}  // namespace hystbench
