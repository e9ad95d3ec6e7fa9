#include "framework/export/ioh_export.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <map>
#include <set>

#include "framework/report/results_merge.hpp"

namespace hystbench {
namespace {
namespace fs = std::filesystem;

// The IOHexperimenter version whose json layout this follows.
constexpr const char* kIohVersion = "0.3.3";
constexpr const char* kSuite = "hystbench";

// Shortest text that reads back to the same double.
std::string exact(double v) {
  char buf[32];
  const auto end = std::to_chars(buf, buf + sizeof buf, v).ptr;
  return {buf, end};
}

struct Function {
  int id;
  std::string name;
  int dimension;
};

// One experiment (its folders merged) and the function it ran on.
struct Group {
  MergedResults merged;
  Function function;
};

std::string problem_name(const ResultsFolder& folder) {
  const auto& problem = folder.summary.value("problem", nlohmann::json::object());
  if (problem.contains("name")) return problem["name"].get<std::string>();
  return folder.summary["experiment"]["problem"].value("type", std::string("problem"));
}

int dimension_of(const ResultsFolder& folder, const MergedResults& merged) {
  const auto& problem = folder.summary.value("problem", nlohmann::json::object());
  if (problem.contains("lower")) return int(problem["lower"].size());
  for (const auto& trials : merged.results)
    for (const auto& t : trials)
      if (!t.best_x.empty()) return int(t.best_x.size());
  return 0;
}

// Slices of one experiment share its name and problem; the same file run on
// other data is another group.
std::vector<Group> group_by_experiment(const std::vector<ResultsFolder>& folders) {
  std::map<std::string, std::vector<ResultsFolder>> by_key;
  std::vector<std::string> order;
  for (const auto& f : folders) {
    const std::string key = f.summary["experiment"].value("name", std::string()) + "\n" +
                            f.summary.value("problem", nlohmann::json()).dump();
    if (!by_key.count(key)) order.push_back(key);
    by_key[key].push_back(f);
  }
  std::map<std::string, int> ids;
  std::vector<Group> groups;
  for (const auto& key : order) {
    const auto& slices = by_key[key];
    MergedResults merged = merge_results(slices);
    const std::string function = ioh_safe_name(problem_name(slices.front()));
    const int id = ids.emplace(function, int(ids.size()) + 1).first->second;
    const int dim = dimension_of(slices.front(), merged);
    groups.push_back({std::move(merged), {id, function, dim}});
  }
  return groups;
}

std::string parameters_text(const AlgorithmSpec& a) {
  std::string text = a.name;
  for (const auto& [key, value] : a.params.items())
    text += " " + key + "=" + (value.is_string() ? value.get<std::string>() : value.dump());
  if (a.polish) text += " polish=" + a.polish->algorithm;
  return text;
}

std::string run_block(const std::vector<std::pair<long, double>>& rows) {
  std::string text = "evaluations raw_y\n";
  for (const auto& [evals, y] : rows) text += std::to_string(evals) + " " + exact(y) + "\n";
  return text;
}

nlohmann::json run_entry(const TrialResult& t, const std::vector<std::pair<long, double>>& rows) {
  long found_at = rows.back().first;
  for (const auto& [evals, y] : rows)
    if (y == t.best) {
      found_at = evals;
      break;
    }
  return {{"instance", 1},
          {"evals", t.evaluations},
          {"best", {{"evals", found_at}, {"y", t.best}, {"x", t.best_x}}}};
}

// The json IOHanalyzer reads first: one scenario, its .dat and its runs.
nlohmann::json meta_data(const Function& f, const std::string& algorithm, const std::string& info,
                         const fs::path& dat, nlohmann::json runs) {
  return {{"version", kIohVersion},
          {"suite", kSuite},
          {"function_id", f.id},
          {"function_name", f.name},
          {"maximization", false},
          {"algorithm", {{"name", algorithm}, {"info", info}}},
          {"attributes", {"evaluations", "raw_y"}},
          {"scenarios",
           {{{"dimension", f.dimension}, {"path", dat.generic_string()}, {"runs", std::move(runs)}}}}};
}

// Adds the json and the .dat of one algorithm of one group.
void export_algorithm(const Group& g, const AlgorithmSpec& spec, const std::string& name,
                      const std::vector<TrialResult>& trials, IohExport& out) {
  const Function& f = g.function;
  const std::string stem = "f" + std::to_string(f.id) + "_" + f.name;
  const fs::path dat = fs::path("data_" + stem) /
                       ("IOHprofiler_f" + std::to_string(f.id) + "_DIM" +
                        std::to_string(f.dimension) + ".dat");
  nlohmann::json runs = nlohmann::json::array();
  std::string data;
  for (const auto& t : trials) {
    // As in the tables: a failed trial has no fitness to show.
    if (t.failed() || !std::isfinite(t.best)) {
      out.skipped.push_back(name + " trial " + std::to_string(t.trial) + ": " +
                            (t.failed() ? "failed (" + t.message + ")" : "no finite fitness"));
      continue;
    }
    const auto rows = ioh_rows(t);
    data += run_block(rows);
    runs.push_back(run_entry(t, rows));
  }
  if (runs.empty()) return;
  out.runs += long(runs.size());
  const nlohmann::json meta = meta_data(f, name, parameters_text(spec), dat, std::move(runs));
  const fs::path folder = ioh_safe_name(name);
  out.files.push_back({folder / ("IOHprofiler_" + stem + ".json"), meta.dump(2) + "\n"});
  out.files.push_back({folder / dat, data});
}

}  // namespace

std::string ioh_safe_name(const std::string& name) {
  std::string safe;
  for (const unsigned char c : name) {
    const char kept = std::isalnum(c) || c == '-' || c == '.' ? char(c) : '_';
    if (kept != '_' || (!safe.empty() && safe.back() != '_')) safe += kept;
  }
  while (!safe.empty() && safe.back() == '_') safe.pop_back();
  return safe.empty() ? "unnamed" : safe;
}

std::vector<std::pair<long, double>> ioh_rows(const TrialResult& trial) {
  std::vector<std::pair<long, double>> rows;
  for (const auto& p : trial.trace)
    if (std::isfinite(p.best) && (rows.empty() || p.best < rows.back().second))
      rows.emplace_back(p.evaluations, p.best);
  if (rows.empty() || trial.evaluations > rows.back().first)
    rows.emplace_back(trial.evaluations, trial.best);
  return rows;
}

namespace {

// The label, or label@experiment (then label@experiment-2, ...) when another
// algorithm already has that name, as a file name, on this function.
std::string unique_name(const Group& g, const std::string& label,
                        std::set<std::pair<int, std::string>>& taken) {
  std::string name = label;
  for (int n = 1; !taken.emplace(g.function.id, ioh_safe_name(name)).second; ++n)
    name = label + "@" + g.merged.experiment.name + (n > 1 ? std::string("-").append(std::to_string(n)) : "");
  return name;
}

}  // namespace

IohExport export_ioh(const std::vector<ResultsFolder>& folders) {
  const auto groups = group_by_experiment(folders);
  IohExport out;
  std::set<std::pair<int, std::string>> taken;  // (function, folder name)
  for (const auto& g : groups)
    for (std::size_t a = 0; a < g.merged.experiment.algorithms.size(); ++a) {
      const auto& spec = g.merged.experiment.algorithms[a];
      export_algorithm(g, spec, unique_name(g, spec.label, taken), g.merged.results[a], out);
    }
  return out;
}

}  // namespace hystbench
