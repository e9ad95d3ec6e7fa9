#pragma once
// The messages of a distributed run (MPI build). A rank > 0 asks rank 0 for
// work saying how many trials it runs at once; rank 0 answers with a chunk,
// empty when nothing is left; the rank sends each finished trial as its
// trials.jsonl line (JSON keeps every double exact), then asks again.
#include <optional>

#include "framework/cluster/trial_chunk.hpp"
#include "framework/harness/trial_result.hpp"

namespace hystbench::cluster {

enum class MessageKind { Ask = 1, Chunk = 2, Result = 3 };

struct Incoming {
  int source;
  MessageKind kind;
};

// Rank > 0 side.
void send_ask(long capacity);
TrialChunk receive_chunk();
void send_result(const TrialResult& r);

// Rank 0 side. poll() does not wait: rank 0 runs trials of its own.
std::optional<Incoming> poll();
long receive_ask(int source);
void send_chunk(int destination, const TrialChunk& chunk);
TrialResult receive_result(int source);

}  // namespace hystbench::cluster
