// Rank 0 of a distributed run (MPI build): hands out chunks of trials,
// collects what the other ranks finish, and runs trials itself meanwhile.
#include <chrono>
#include <exception>
#include <iostream>
#include <thread>

#include "framework/cluster/cluster.hpp"
#include "framework/cluster/input_agreement.hpp"
#include "framework/cluster/result_collector.hpp"
#include "framework/cluster/task_dispenser.hpp"
#include "framework/cluster/trial_messages.hpp"

namespace hystbench::cluster {
namespace {

// Answers the other ranks until each has been told that nothing is left.
// Polls with short sleeps instead of a blocking receive, which in common MPI
// libraries spins and would take a core from rank 0's own trials.
void serve_ranks(TaskDispenser& dispenser, ResultCollector& collector) {
  int finished_ranks = 0;
  while (finished_ranks < size() - 1) {
    const auto message = poll();
    if (!message) {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
      continue;
    }
    if (message->kind == MessageKind::Result) {
      try {
        collector.add(receive_result(message->source));
      } catch (...) {  // a line that does not parse
        collector.fail(std::current_exception());
      }
      if (collector.failed()) dispenser.stop();
    } else {
      const TrialChunk chunk = dispenser.take(receive_ask(message->source));
      send_chunk(message->source, chunk);
      if (chunk.empty()) ++finished_ranks;
    }
  }
}

void run_own_trials(const Problem& problem, const Experiment& experiment, int threads,
                    TaskDispenser& dispenser, ResultCollector& collector) {
  for (TrialChunk chunk = dispenser.take(threads); !chunk.empty(); chunk = dispenser.take(threads)) {
    run_chunk(problem, experiment, chunk, threads, [&](const TrialResult& r) { collector.add(r); });
    if (collector.failed()) dispenser.stop();
  }
}

}  // namespace

std::vector<std::vector<TrialResult>> run_campaign(const Problem& problem,
                                                   const Experiment& experiment,
                                                   const CampaignOptions& options) {
  if (size() == 1) return hystbench::run_campaign(problem, experiment, options);
  agree_inputs_read(experiment, problem);
  const TrialRange trials =
      options.trials.size() > 0 ? options.trials : TrialRange{0, experiment.trials};
  const int algorithms = static_cast<int>(experiment.algorithms.size());
  TaskDispenser dispenser(algorithms, trials);
  ResultCollector collector(algorithms, trials, options.on_trial_done);
  for (const TrialResult& r : options.finished) {  // kept by `run --resume`
    dispenser.skip(r.algorithm_index, r.trial);
    collector.keep(r);
  }
  std::cerr << "Trials handed out to " << size() << " MPI ranks as they ask for work\n";

  std::exception_ptr serving_error;
  std::thread server([&] {
    try {
      serve_ranks(dispenser, collector);
    } catch (...) {
      serving_error = std::current_exception();
    }
  });
  try {
    run_own_trials(problem, experiment, options.threads, dispenser, collector);
  } catch (...) {
    // The other ranks still finish their chunks and are told to stop.
    dispenser.stop();
    server.join();
    throw;
  }
  server.join();
  if (serving_error) std::rethrow_exception(serving_error);
  return collector.take_results();
}

}  // namespace hystbench::cluster
