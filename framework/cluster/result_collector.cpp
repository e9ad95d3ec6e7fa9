#include "framework/cluster/result_collector.hpp"

#include <stdexcept>
#include <string>

namespace hystbench::cluster {

ResultCollector::ResultCollector(int algorithms, TrialRange trials,
                                 std::function<void(const TrialResult&)> on_trial_done)
    : trials_(trials),
      on_trial_done_(std::move(on_trial_done)),
      results_(algorithms, std::vector<TrialResult>(trials.size())),
      present_(algorithms, std::vector<bool>(trials.size(), false)) {}

void ResultCollector::add(TrialResult r) {
  std::lock_guard<std::mutex> lock(mutex_);
  try {
    place(std::move(r), true);
  } catch (...) {
    if (!error_) error_ = std::current_exception();
  }
}

void ResultCollector::keep(TrialResult r) {
  std::lock_guard<std::mutex> lock(mutex_);
  place(std::move(r), false);
}

// Checked because a result from another rank crossed a process boundary.
void ResultCollector::place(TrialResult r, bool report) {
  const int a = r.algorithm_index;
  const long t = r.trial;
  if (a < 0 || a >= int(results_.size()) || t < trials_.first || t >= trials_.end ||
      present_[a][t - trials_.first])
    throw std::runtime_error("a rank sent trial " + std::to_string(t) + " of algorithm " +
                             std::to_string(a) + ", which was not handed out");
  present_[a][t - trials_.first] = true;
  if (report && on_trial_done_ && !error_) on_trial_done_(r);
  results_[a][t - trials_.first] = std::move(r);
}

void ResultCollector::fail(std::exception_ptr error) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!error_) error_ = error;
}

bool ResultCollector::failed() {
  std::lock_guard<std::mutex> lock(mutex_);
  return error_ != nullptr;
}

std::vector<std::vector<TrialResult>> ResultCollector::take_results() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (error_) std::rethrow_exception(error_);
  return std::move(results_);
}

}  // namespace hystbench::cluster
