#include "framework/report/results_merge.hpp"

#include <algorithm>
#include <set>
#include <utility>

#include "framework/core/error.hpp"

namespace hystbench {
namespace {

// Build identity only: the same experiment on other hosts, dates or thread
// counts gives the same trials.
constexpr const char* kProvenanceFields[] = {"version", "git_commit"};

std::string join_path(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

void require_same(const ResultsFolder& first, const ResultsFolder& other) {
  const auto refuse = [&](const std::string& field) {
    throw InputError(field + " differs between " + first.dir.string() + " and " +
                     other.dir.string() + ": only results of one experiment, on the same data and "
                     "from the same build, can be merged");
  };
  for (const char* part : {"experiment", "problem"})
    if (auto d = first_difference(first.summary[part], other.summary[part], part); !d.empty())
      refuse(d);
  for (const char* field : kProvenanceFields)
    if (first.summary["provenance"].value(field, nlohmann::json()) !=
        other.summary["provenance"].value(field, nlohmann::json()))
      refuse(std::string("provenance.") + field);
}

Experiment experiment_of(const ResultsFolder& folder) {
  Experiment e = Experiment::from_json(folder.summary["experiment"],
                                       (folder.dir / "summary.json").string() + " experiment");
  // Written relative to the folder (absolute by older versions).
  const std::filesystem::path base = folder.summary.value("experiment_dir", std::string("."));
  e.base_dir = (base.is_absolute() ? base : folder.dir / base).lexically_normal().string();
  return e;
}

void check_trial(const Experiment& e, const ResultsFolder& folder, const TrialResult& r) {
  const std::string where = (folder.dir / "trials.jsonl").string() + ": trial " +
                            std::to_string(r.trial) + " of " + r.label;
  if (r.algorithm_index < 0 || std::size_t(r.algorithm_index) >= e.algorithms.size() ||
      e.algorithms[r.algorithm_index].label != r.label)
    throw InputError(where + ": the experiment has no such algorithm at index " +
                     std::to_string(r.algorithm_index));
  if (r.trial < 0 || r.trial >= e.trials)
    throw InputError(where + ": trial index outside the experiment's " +
                     std::to_string(e.trials) + " trials");
}

}  // namespace

std::string first_difference(const nlohmann::json& a, const nlohmann::json& b,
                             const std::string& path) {
  if (a.is_object() && b.is_object()) {
    std::set<std::string> keys;
    for (const auto& [k, v] : a.items()) keys.insert(k);
    for (const auto& [k, v] : b.items()) keys.insert(k);
    for (const auto& k : keys) {
      if (!a.contains(k) || !b.contains(k)) return join_path(path, k);
      if (auto d = first_difference(a[k], b[k], join_path(path, k)); !d.empty()) return d;
    }
    return "";
  }
  if (a.is_array() && b.is_array() && a.size() == b.size()) {
    for (std::size_t i = 0; i < a.size(); ++i)
      if (auto d = first_difference(a[i], b[i], path + "[" + std::to_string(i) + "]"); !d.empty())
        return d;
    return "";
  }
  return a == b ? "" : (path.empty() ? "value" : path);
}

MergedResults merge_results(const std::vector<ResultsFolder>& folders) {
  if (folders.empty()) throw InputError("no results folders given");
  for (std::size_t i = 1; i < folders.size(); ++i) require_same(folders[0], folders[i]);
  MergedResults m{experiment_of(folders[0]), {}};
  m.results.resize(m.experiment.algorithms.size());
  std::set<std::pair<int, long>> seen;
  for (const auto& folder : folders)
    for (const auto& r : folder.trials) {
      check_trial(m.experiment, folder, r);
      if (!seen.insert({r.algorithm_index, r.trial}).second)
        throw InputError("trial " + std::to_string(r.trial) + " of " + r.label + " appears twice (" +
                         (folder.dir / "trials.jsonl").string() +
                         "): merge only folders holding disjoint trials");
      m.results[r.algorithm_index].push_back(r);
    }
  for (auto& trials : m.results)
    std::sort(trials.begin(), trials.end(),
              [](const TrialResult& a, const TrialResult& b) { return a.trial < b.trial; });
  return m;
}

}  // namespace hystbench
