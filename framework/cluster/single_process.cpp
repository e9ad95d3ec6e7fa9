// The cluster interface of a build without MPI: one rank, plain runs.
#include <stdexcept>

#include "framework/cluster/cluster.hpp"

namespace hystbench::cluster {

Session::Session(int&, char**&) {}
Session::~Session() = default;

int rank() { return 0; }
int size() { return 1; }

void run_on_all_ranks(const std::function<void()>& body) { body(); }

std::vector<std::vector<TrialResult>> run_campaign(const Problem& problem,
                                                   const Experiment& experiment,
                                                   const CampaignOptions& options) {
  return hystbench::run_campaign(problem, experiment, options);
}

void serve_trials(const Problem&, const Experiment&, int) {
  throw std::logic_error("serve_trials: there are no other ranks in a build without MPI");
}

}  // namespace hystbench::cluster
