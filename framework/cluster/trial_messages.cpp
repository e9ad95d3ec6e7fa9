#include "framework/cluster/trial_messages.hpp"

#include <mpi.h>

#include <string>

namespace hystbench::cluster {
namespace {

constexpr int coordinator = 0;

int tag(MessageKind kind) { return static_cast<int>(kind); }

}  // namespace

void send_ask(long capacity) {
  MPI_Send(&capacity, 1, MPI_LONG, coordinator, tag(MessageKind::Ask), MPI_COMM_WORLD);
}

TrialChunk receive_chunk() {
  long fields[3];
  MPI_Recv(fields, 3, MPI_LONG, coordinator, tag(MessageKind::Chunk), MPI_COMM_WORLD,
           MPI_STATUS_IGNORE);
  return {static_cast<int>(fields[0]), {fields[1], fields[2]}};
}

void send_result(const TrialResult& r) {
  const std::string line = r.to_json().dump();
  MPI_Send(line.data(), static_cast<int>(line.size()), MPI_CHAR, coordinator,
           tag(MessageKind::Result), MPI_COMM_WORLD);
}

std::optional<Incoming> poll() {
  int arrived = 0;
  MPI_Status status;
  MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &arrived, &status);
  if (!arrived) return std::nullopt;
  return Incoming{status.MPI_SOURCE, static_cast<MessageKind>(status.MPI_TAG)};
}

long receive_ask(int source) {
  long capacity = 1;
  MPI_Recv(&capacity, 1, MPI_LONG, source, tag(MessageKind::Ask), MPI_COMM_WORLD,
           MPI_STATUS_IGNORE);
  return capacity;
}

void send_chunk(int destination, const TrialChunk& chunk) {
  long fields[3] = {chunk.algorithm, chunk.trials.first, chunk.trials.end};
  MPI_Send(fields, 3, MPI_LONG, destination, tag(MessageKind::Chunk), MPI_COMM_WORLD);
}

TrialResult receive_result(int source) {
  MPI_Status status;
  MPI_Probe(source, tag(MessageKind::Result), MPI_COMM_WORLD, &status);
  int bytes = 0;
  MPI_Get_count(&status, MPI_CHAR, &bytes);
  std::string line(static_cast<std::size_t>(bytes), '\0');
  MPI_Recv(line.data(), bytes, MPI_CHAR, source, tag(MessageKind::Result), MPI_COMM_WORLD,
           MPI_STATUS_IGNORE);
  return TrialResult::from_json(nlohmann::json::parse(line));
}

}  // namespace hystbench::cluster
