#pragma once
// One `hystbench run` spread over the processes (ranks) started by
// `mpirun -np K` or `srun`. Rank 0 coordinates: it hands out chunks of
// trials, runs trials itself between messages, and alone writes the results
// folder. The other ranks run the chunks they are given and send each
// finished trial back at once. Without MPI (a build without it, or a process
// not started by an MPI launcher) there is one rank and a run is a plain run.
#include <functional>
#include <vector>

#include "framework/core/problem.hpp"
#include "framework/harness/campaign.hpp"
#include "framework/harness/experiment.hpp"
#include "framework/harness/trial_result.hpp"

namespace hystbench::cluster {

// Starts and ends MPI for the life of `main`, when the process was started by
// an MPI launcher; does nothing otherwise.
class Session {
 public:
  Session(int& argc, char**& argv);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;
};

int rank();
int size();
// Rank 0: the only rank that prints, writes files and runs the other commands.
inline bool is_coordinator() { return rank() == 0; }
inline bool is_worker() { return rank() != 0; }

// Thrown on a rank that stops because another rank could not start the run;
// the rank that failed reports why, this one only exits with the code.
struct RankStopped {
  int exit_code;
};

// Runs the `run` command on this rank. An error on any rank before the
// trials start stops every rank with the same exit code and one message,
// instead of leaving the others waiting for messages that never come.
void run_on_all_ranks(const std::function<void()>& body);

// Rank 0: run_campaign with the trials spread over all ranks; the same
// results, callback and exceptions as run_campaign. With one rank it is
// run_campaign.
std::vector<std::vector<TrialResult>> run_campaign(const Problem& problem,
                                                   const Experiment& experiment,
                                                   const CampaignOptions& options);

// Ranks > 0: run the trials rank 0 hands out, with `threads` threads, until it
// says there are none left.
void serve_trials(const Problem& problem, const Experiment& experiment, int threads);

}  // namespace hystbench::cluster
