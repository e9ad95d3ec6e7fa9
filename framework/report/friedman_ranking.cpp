#include "framework/report/friedman_ranking.hpp"

#include <algorithm>
#include <limits>
#include <map>

#include "framework/core/error.hpp"
#include "framework/report/results_folder.hpp"
#include "framework/stats/descriptive.hpp"
#include "framework/stats/ranks.hpp"

namespace hystbench {
namespace {

std::vector<std::string> algorithm_labels(const ResultsFolder& folder) {
  std::vector<std::string> labels;
  for (const auto& a : folder.summary.at("experiment").at("algorithms"))
    labels.push_back(a.at("label").get<std::string>());
  return labels;
}

std::string folder_name(const ResultsFolder& folder) {
  const auto name = folder.dir.lexically_normal().filename().string();
  return name.empty() ? folder.dir.lexically_normal().parent_path().filename().string() : name;
}

// Final fitness of every trial per label, in trial order: trials.jsonl is
// in finishing order, which varies with threads, and the mean must not
// depend on it. A failed trial counts as +inf so that it ranks its
// algorithm last rather than vanishing from the mean.
std::map<std::string, std::vector<double>> finals_by_label(const ResultsFolder& folder) {
  std::vector<const TrialResult*> trials;
  for (const auto& t : folder.trials) trials.push_back(&t);
  std::stable_sort(trials.begin(), trials.end(),
                   [](const TrialResult* a, const TrialResult* b) { return a->trial < b->trial; });
  std::map<std::string, std::vector<double>> finals;
  for (const auto* t : trials)
    finals[t->label].push_back(t->failed() ? std::numeric_limits<double>::infinity() : t->best);
  return finals;
}

void check_same_algorithms(const std::vector<std::string>& labels, const ResultsFolder& folder,
                           const std::string& first) {
  const auto here = algorithm_labels(folder);
  for (const auto& l : labels)
    if (std::find(here.begin(), here.end(), l) == here.end())
      throw InputError(folder.dir.string() + ": has no algorithm \"" + l + "\", which " + first +
                       " has; every folder ranked together must hold the same algorithms");
  for (const auto& l : here)
    if (std::find(labels.begin(), labels.end(), l) == labels.end())
      throw InputError(folder.dir.string() + ": has algorithm \"" + l + "\", which " + first +
                       " has not; every folder ranked together must hold the same algorithms");
}

std::vector<double> block_values(const ResultsFolder& folder,
                                 const std::vector<std::string>& labels, RankStatistic statistic) {
  const auto finals = finals_by_label(folder);
  std::vector<double> values;
  for (const auto& l : labels) {
    const auto it = finals.find(l);
    if (it == finals.end())
      throw InputError(folder.dir.string() + ": trials.jsonl has no trial of \"" + l + "\"");
    values.push_back(statistic == RankStatistic::Mean ? stats::mean(it->second)
                                                      : stats::median(it->second));
  }
  return values;
}

int control_index(const FriedmanRanking& r, const std::string& control) {
  if (control.empty()) {
    const auto& avg = r.test.average_ranks;
    return static_cast<int>(std::min_element(avg.begin(), avg.end()) - avg.begin());
  }
  const auto it = std::find(r.labels.begin(), r.labels.end(), control);
  if (it == r.labels.end())
    throw InputError("--control " + control + ": no algorithm has this label; the folders hold " +
                     [&] {
                       std::string all;
                       for (const auto& l : r.labels) all += (all.empty() ? "" : ", ") + l;
                       return all;
                     }());
  return static_cast<int>(it - r.labels.begin());
}

}  // namespace

std::string to_string(RankStatistic s) { return s == RankStatistic::Mean ? "mean" : "median"; }

FriedmanRanking rank_folders(const std::vector<ResultsFolder>& folders, RankStatistic statistic,
                             const std::string& control) {
  if (folders.size() < 2)
    throw InputError("rank: needs results folders of at least 2 problems or data sets, got " +
                     std::to_string(folders.size()));
  FriedmanRanking r;
  r.statistic = statistic;
  r.labels = algorithm_labels(folders[0]);
  for (const auto& f : folders) {
    check_same_algorithms(r.labels, f, folders[0].dir.string());
    r.blocks.push_back(folder_name(f));
    r.problems.push_back(f.summary.value("problem", nlohmann::json::object()).value("name", ""));
    r.trials.push_back(std::count_if(f.trials.begin(), f.trials.end(),
                                     [&](const TrialResult& t) { return t.label == r.labels[0]; }));
    r.budgets.push_back(describe_budget(
        Budget::from_json(f.summary.at("experiment").at("budget"), "experiment.budget")));
    r.values.push_back(block_values(f, r.labels, statistic));
    r.ranks.push_back(stats::average_ranks(r.values.back()));
  }
  r.test = stats::friedman_test(r.values);
  const int k = static_cast<int>(r.labels.size());
  if (k <= 10) r.critical_difference = stats::nemenyi_critical_difference(k, r.test.blocks);
  r.control = control_index(r, control);
  r.control_chosen = !control.empty();
  r.versus_control = stats::compare_with_control(r.test, r.control);
  return r;
}

}  // namespace hystbench
