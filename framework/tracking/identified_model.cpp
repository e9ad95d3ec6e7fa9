#include "framework/tracking/identified_model.hpp"

#include <cmath>

#include "framework/control/model_stream.hpp"
#include "framework/core/error.hpp"
#include "framework/core/text.hpp"
#include "framework/io/data_path.hpp"
#include "framework/io/json_file.hpp"
#include "framework/svr/svr_stream.hpp"

namespace hystbench {
namespace {

class CatalogModel final : public IdentifiedModel {
 public:
  CatalogModel(const ResolvedModel& m, double sample_time)
      : model_(streaming_model(m, sample_time, "identified")),
        scratch_(std::make_unique<StreamingModel>(*model_)),
        u_(m.scales.u),
        y_(m.scales.y) {}
  CatalogModel(const CatalogModel& o)
      : model_(std::make_unique<StreamingModel>(*o.model_)),
        scratch_(std::make_unique<StreamingModel>(*o.scratch_)),
        u_(o.u_),
        y_(o.y_) {}

  void reset() override { model_->reset(); }
  double trial_front(double u) override {
    scratch_->copy_front_state(*model_);
    return y_ * scratch_->step_front(u / u_);
  }
  double step_front(double u) override { return y_ * model_->step_front(u / u_); }
  double step_back(double w) override { return y_ * model_->step_back(w / y_); }
  std::unique_ptr<IdentifiedModel> clone() const override { return std::make_unique<CatalogModel>(*this); }

 private:
  std::unique_ptr<StreamingModel> model_, scratch_;
  double u_, y_;  // the fit's scales: the model works on u / u_ and answers in units of y_
};

class SvrModel final : public IdentifiedModel {
 public:
  explicit SvrModel(std::shared_ptr<const SvrHammerstein> m) : model_(std::move(m)), stream_(*model_) {}
  SvrModel(const SvrModel& o) : model_(o.model_), stream_(o.stream_) {}

  void reset() override { stream_.reset(); }
  double trial_front(double u) override { return stream_.predict_front(u); }
  double step_front(double u) override { return stream_.step_front(u); }
  double step_back(double w) override { return stream_.step_back(w); }
  std::unique_ptr<IdentifiedModel> clone() const override { return std::make_unique<SvrModel>(*this); }

 private:
  std::shared_ptr<const SvrHammerstein> model_;  // the stream points into it
  SvrStream stream_;
};

IdentifiedSource svr_source(const nlohmann::json& spec, const std::filesystem::path& base, const std::string& where) {
  if (!spec["svr"].is_string()) throw InputError(where + ".svr: give the path of an svr_model.json");
  const auto path = resolve_data_path(spec["svr"].get<std::string>(), base, where + ".svr");
  const nlohmann::json j = read_json_file(path, "SVR model");
  auto model = std::make_shared<const SvrHammerstein>(SvrHammerstein::from_json(j, path.string()));
  const double ts = j.value("sample_time", 0.0);
  if (!(ts > 0.0)) throw InputError(path.string() + ".sample_time: missing; write the model with `hystbench svr`");
  const auto name = path.parent_path().filename() / path.filename();
  return {name.string() + ": " + model->describe(), ts, [model, ts, path](double sample_time) {
            if (std::abs(sample_time - ts) > 1e-6 * ts)
              throw InputError(path.string() + ": the SVR model's lags count samples at " +
                               format_number("%g", 1.0 / ts) + " Hz, not the loop's " +
                               format_number("%g", 1.0 / sample_time) + " Hz; run the loop at the model's rate "
                               "(sample_rate) or identify the model at the loop's");
            return std::unique_ptr<IdentifiedModel>(std::make_unique<SvrModel>(model));
          }};
}

}  // namespace

IdentifiedSource read_identified(const nlohmann::json& spec, const std::filesystem::path& base,
                                 const std::string& where) {
  if (spec.is_object() && spec.contains("svr")) {
    if (spec.size() != 1) throw InputError(where + ": an SVR model takes no other key than \"svr\"");
    return svr_source(spec, base, where);
  }
  const ResolvedModel m = resolve_model(spec, base, where);
  return {m.description, 0.0, [m](double sample_time) {
            return std::unique_ptr<IdentifiedModel>(std::make_unique<CatalogModel>(m, sample_time));
          }};
}

}  // namespace hystbench
