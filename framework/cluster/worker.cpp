// A rank > 0 of a distributed run (MPI build): runs the chunks rank 0 hands
// out and sends every finished trial back at once, so that a rank that dies
// loses only the trials it was running.
#include "framework/cluster/cluster.hpp"
#include "framework/cluster/input_agreement.hpp"
#include "framework/cluster/trial_messages.hpp"

namespace hystbench::cluster {

void serve_trials(const Problem& problem, const Experiment& experiment, int threads) {
  agree_inputs_read(experiment, problem);
  for (;;) {
    send_ask(threads);
    const TrialChunk chunk = receive_chunk();
    if (chunk.empty()) return;
    run_chunk(problem, experiment, chunk, threads, send_result);
  }
}

}  // namespace hystbench::cluster
