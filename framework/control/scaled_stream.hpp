#pragma once
// A stream between physical units and another stream's own units:
// y = output_scale * inner(input_offset + input_scale * u). A fitted model works on data
// normalised by its RMS (u / scales.u, y / scales.y); inside a loop it
// reads volts and answers in sensor units.
#include <memory>

#include "framework/model/signal_stream.hpp"

namespace hystbench {

class ScaledStream final : public SignalStream {
 public:
  ScaledStream(std::unique_ptr<SignalStream> inner, double input_scale, double output_scale,
               double input_offset = 0.0)
      : inner_(std::move(inner)),
        input_scale_(input_scale),
        output_scale_(output_scale),
        input_offset_(input_offset) {}
  ScaledStream(const ScaledStream& other)
      : inner_(other.inner_->clone()),
        input_scale_(other.input_scale_),
        output_scale_(other.output_scale_),
        input_offset_(other.input_offset_) {}

  void set_output_scale(double scale) { output_scale_ = scale; }
  void reset() override { inner_->reset(); }
  double step(double u) override {
    return output_scale_ * inner_->step(input_offset_ + input_scale_ * u);
  }
  std::unique_ptr<SignalStream> clone() const override {
    return std::make_unique<ScaledStream>(*this);
  }

 private:
  std::unique_ptr<SignalStream> inner_;
  double input_scale_, output_scale_, input_offset_;
};

// Two streams in series: y = second(first(u)).
class SeriesStream final : public SignalStream {
 public:
  SeriesStream(std::unique_ptr<SignalStream> first, std::unique_ptr<SignalStream> second)
      : first_(std::move(first)), second_(std::move(second)) {}
  SeriesStream(const SeriesStream& other)
      : first_(other.first_->clone()), second_(other.second_->clone()) {}

  void reset() override {
    first_->reset();
    second_->reset();
  }
  double step(double u) override { return second_->step(first_->step(u)); }
  std::unique_ptr<SignalStream> clone() const override {
    return std::make_unique<SeriesStream>(*this);
  }

 private:
  std::unique_ptr<SignalStream> first_, second_;
};

}  // namespace hystbench
