#include "framework/core/registry.hpp"


namespace hystbench {

std::unique_ptr<Optimizer> make_optimizer(const std::string& name, const nlohmann::json& params,
                                          const std::string& where) {
  const OptimizerInfo& info = OptimizerRegistry::instance().find(name, where + ".name");
  return info.create(validate_params(info.params, params, where + ".params"));
}

}  // namespace hystbench

namespace hystbench {

std::unique_ptr<Problem> make_problem(const nlohmann::json& spec,
                                      const std::filesystem::path& base_dir) {
  const auto& info = ProblemRegistry::instance().find(spec.value("type", ""), "problem.type");
  return info.create(spec, base_dir);
}

}  // namespace hystbench
