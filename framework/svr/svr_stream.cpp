#include "framework/svr/svr_stream.hpp"

namespace hystbench {

SvrStream::SvrStream(const SvrHammerstein& model) : model_(&model) { reset(); }

void SvrStream::reset() {
  const SvrLags& l = model_->lags();
  row_.resize(l.dimension());
  row_.head(l.m + 1).setConstant(model_->input_scale().to_unit(0.0));
  row_.segment(l.m + 1, l.n + 1).setConstant(model_->output_scale().to_unit(0.0));
  if (l.input_rate) row_[l.m + l.n + 2] = 0.0;
  const auto& arx = model_->arx();
  back_in_.assign(arx ? arx->q : 0, 0.0);
  back_out_.assign(arx ? arx->p : 0, 0.0);
}

// Not safe to call on one stream from two threads (it writes row_[0]);
// every loop has a stream of its own.
double SvrStream::predict_front(double u) const {
  const Eigen::Index last = row_.size() - 1;  // the rate, or an output lag set_input leaves alone
  const double kept_x = row_[0], kept_last = row_[last];
  set_input(u);
  const double w = model_->regressor().predict(row_);
  row_[0] = kept_x;
  row_[last] = kept_last;
  return model_->output_scale().from_unit(w);
}

// x(k) into the row; row_[0] still holds x(k-1), which the rate needs.
void SvrStream::set_input(double u) const {
  const SvrLags& l = model_->lags();
  const double x = model_->input_scale().to_unit(u);
  if (l.input_rate) row_[l.m + l.n + 2] = model_->rate_feature(row_[0], x);
  row_[0] = x;
}

double SvrStream::step_front(double u) {
  const SvrLags& l = model_->lags();
  set_input(u);
  const double w = model_->regressor().predict(row_);
  // Shift: x(k) becomes x(k−1), the new w becomes w(k).
  for (int i = l.m; i > 0; --i) row_[i] = row_[i - 1];
  for (int i = l.n; i > 0; --i) row_[l.m + 1 + i] = row_[l.m + i];
  row_[l.m + 1] = w;
  return model_->output_scale().from_unit(w);
}

double SvrStream::step_back(double w) {
  const auto& arx = model_->arx();
  if (!arx) return w;
  if (!back_in_.empty()) {
    back_in_.insert(back_in_.begin(), w);
    back_in_.pop_back();
  }
  double y = 0.0;
  for (int j = 0; j < arx->q; ++j) y += arx->b[j] * back_in_[j];
  for (int i = 0; i < arx->p; ++i) y -= arx->a[i] * back_out_[i];
  if (!back_out_.empty()) {
    back_out_.insert(back_out_.begin(), y);
    back_out_.pop_back();
  }
  return y;
}

}  // namespace hystbench
