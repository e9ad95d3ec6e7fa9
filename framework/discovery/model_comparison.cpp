#include "framework/discovery/model_comparison.hpp"

namespace hystbench {

ComparisonInput comparison_input(const ModelData& data, Eigen::VectorXd y_model,
                                 const std::string& u_unit, const std::string& y_unit) {
  ComparisonInput in;
  in.t = data.t;
  in.u = data.u * data.scales.u;
  in.y = data.y * data.scales.y;
  in.y_model = std::move(y_model);
  in.segment = data.segment;
  in.estimation = data.estimation;
  in.sample_time = data.sample_time;
  in.u_unit = u_unit;
  in.y_unit = y_unit;
  return in;
}

}  // namespace hystbench
