#include "framework/core/registry.hpp"

namespace hystbench {

std::unique_ptr<Optimizer> make_optimizer(const std::string& name, const nlohmann::json& params,
                                          const std::string& where) {
  const OptimizerInfo& info = OptimizerRegistry::instance().find(name, where + ".name");
  return info.create(validate_params(info.params, params, where + ".params"));
}

}  // namespace hystbench

namespace hystbench {

namespace {

const ProblemInfo& problem_info(const nlohmann::json& spec) {
  if (!spec.is_object() || !spec.contains("type") || !spec["type"].is_string())
    throw InputError("problem.type: missing; e.g. \"hammerstein\" or \"function\"");
  return ProblemRegistry::instance().find(spec["type"].get<std::string>(), "problem.type");
}

Params options_of(const ProblemInfo& info, const nlohmann::json& spec) {
  nlohmann::json options = spec;
  options.erase("type");
  return validate_params(info.params, options, "problem");
}

}  // namespace

Params problem_options(const nlohmann::json& spec) { return options_of(problem_info(spec), spec); }

std::unique_ptr<Problem> make_problem(const nlohmann::json& spec,
                                      const std::filesystem::path& base_dir) {
  const ProblemInfo& info = problem_info(spec);
  return info.create(options_of(info, spec), base_dir);
}

}  // namespace hystbench
