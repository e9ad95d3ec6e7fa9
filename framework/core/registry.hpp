#pragma once
// Name -> factory tables for plugins, filled at static-initialisation time by
// one macro per plugin:
//
//   class MyOptimizer : public hystbench::Optimizer {
//    public:
//     static hystbench::OptimizerInfo info();   // name, parameters, citation
//     explicit MyOptimizer(const hystbench::Params& params);
//     void run(hystbench::EvaluationContext& ctx) override;
//   };
//   HYSTBENCH_OPTIMIZER(MyOptimizer)
//
// Problems register the same way with HYSTBENCH_PROBLEM.
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "framework/core/error.hpp"
#include "framework/core/optimizer.hpp"
#include "framework/core/parameters.hpp"
#include "framework/core/plugin_loader.hpp"
#include "framework/core/problem.hpp"
#include "framework/core/text.hpp"

namespace hystbench {

struct OptimizerInfo {
  std::string name;      // registry key, as written in experiment files
  std::string summary;   // one line
  std::string citation;  // reference; say here what is a reconstruction
  std::vector<ParamSpec> params;
  // Filled in by HYSTBENCH_OPTIMIZER; plugins leave it out.
  std::function<std::unique_ptr<Optimizer>(const Params&)> create = nullptr;
};

struct ProblemInfo {
  std::string name;
  std::string summary;
  // The keys of the experiment's "problem" object besides "type", checked
  // by the framework as optimizers' parameters are.
  std::vector<ParamSpec> params;
  // Builds from the validated options; relative paths are resolved against
  // `base_dir` when they do not exist as given.
  std::function<std::unique_ptr<Problem>(const Params& options,
                                         const std::filesystem::path& base_dir)>
      create;
};

template <class Info>
class Registry {
 public:
  static Registry& instance() {
    static Registry registry;
    return registry;
  }
  void add(Info info) {
    detail::note_registration(info.name);
    entries_[info.name] = std::move(info);
  }
  // Throws InputError naming the known entries, and how a plugin's are added.
  const Info& find(const std::string& name, const std::string& what) const {
    auto it = entries_.find(name);
    if (it != entries_.end()) return it->second;
    std::vector<std::string> known;
    for (const auto& [key, entry] : entries_) known.push_back(key);
    throw InputError(what + ": unknown name '" + name + "'; known: " + join(known) +
                     ". A plugin's name? Load its library with --plugin PATH.so");
  }
  bool contains(const std::string& name) const { return entries_.count(name) > 0; }
  std::vector<const Info*> all() const {
    std::vector<const Info*> out;
    for (const auto& [name, info] : entries_) out.push_back(&info);
    return out;
  }

 private:
  std::map<std::string, Info> entries_;
};

using OptimizerRegistry = Registry<OptimizerInfo>;
using ProblemRegistry = Registry<ProblemInfo>;

// Validates `params` against the plugin's declared list and builds it.
std::unique_ptr<Optimizer> make_optimizer(const std::string& name, const nlohmann::json& params,
                                          const std::string& where);

namespace detail {
// Adds T::info() to the registry of Info, with a factory that passes the
// create function's arguments to T's constructor. One of these per plugin
// kind's macro (optimizers, effects, controllers, plants).
template <class Info, class T, class... Args>
struct PluginRegistration {
  PluginRegistration() {
    Info info = T::info();
    info.create = [](const Args&... args) { return std::make_unique<T>(args...); };
    Registry<Info>::instance().add(std::move(info));
  }
};
template <class T>
struct ProblemRegistration {
  ProblemRegistration() { ProblemRegistry::instance().add(T::info()); }
};
}  // namespace detail

}  // namespace hystbench

#define HYSTBENCH_CONCAT_INNER(a, b) a##b
#define HYSTBENCH_CONCAT(a, b) HYSTBENCH_CONCAT_INNER(a, b)

// Registers Class in the registry of Info; the remaining arguments are the
// types its constructor takes (those of Info::create).
#define HYSTBENCH_REGISTER_PLUGIN(Info, Class, ...)                                \
  namespace {                                                                      \
  const ::hystbench::detail::PluginRegistration<Info, Class __VA_OPT__(, ) __VA_ARGS__> \
      HYSTBENCH_CONCAT(hystbench_plugin_registration_, __LINE__);                  \
  }

#define HYSTBENCH_OPTIMIZER(Class) \
  HYSTBENCH_REGISTER_PLUGIN(::hystbench::OptimizerInfo, Class, ::hystbench::Params)

#define HYSTBENCH_PROBLEM(Class)                                                   \
  namespace {                                                                      \
  const ::hystbench::detail::ProblemRegistration<Class> HYSTBENCH_CONCAT(          \
      hystbench_problem_registration_, __LINE__);                                  \
  }

namespace hystbench {
// The options of an experiment's "problem" object checked against its
// type's declared list (InputError naming "problem.<key>").
Params problem_options(const nlohmann::json& spec);

// Builds the problem described by an experiment's "problem" object.
std::unique_ptr<Problem> make_problem(const nlohmann::json& spec,
                                      const std::filesystem::path& base_dir);
}  // namespace hystbench
