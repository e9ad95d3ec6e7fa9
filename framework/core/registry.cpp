#include "framework/core/registry.hpp"

#include "framework/core/error.hpp"
#include "framework/core/text.hpp"
#include "framework/model/effect.hpp"

namespace hystbench {

template <class Info>
const Info& Registry<Info>::find(const std::string& name, const std::string& what) const {
  auto it = entries_.find(name);
  if (it != entries_.end()) return it->second;
  std::vector<std::string> known;
  for (const auto& [key, info] : entries_) known.push_back(key);
  throw InputError(what + ": unknown name '" + name + "'; known: " + join(known));
}

template class Registry<OptimizerInfo>;
template class Registry<ProblemInfo>;
template class Registry<EffectInfo>;

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
