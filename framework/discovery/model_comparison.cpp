#include "framework/discovery/model_comparison.hpp"

namespace hystbench {

ComparisonInput comparison_input(const ModelData& data, Eigen::VectorXd y_model,
                                 const std::string& u_unit, const std::string& y_unit) {
  const Eigen::Index w = data.warmup, n = data.size() - w;
  ComparisonInput in;
  in.t = data.t.tail(n);
  in.u = data.u.tail(n) * data.scales.u;
  in.y = data.y.tail(n) * data.scales.y;
  in.y_model = y_model.tail(n);
  if (!data.segment.empty()) in.segment.assign(data.segment.begin() + w, data.segment.end());
  in.estimation = data.estimation.tail(n);
  in.first_sample = w;
  in.sample_time = data.sample_time;
  in.u_unit = u_unit;
  in.y_unit = y_unit;
  return in;
}

StartupTransient startup_transient(const ModelData& data, const Eigen::VectorXd& y_model) {
  const ComparisonInput in = comparison_input(data, y_model * data.scales.y, "", "");
  const ExcitationContent c = describe_excitation(in.u, in.segment, in.sample_time, in.u_unit);
  return find_startup_transient(in.y - in.y_model, c, in.first_sample);
}

}  // namespace hystbench
