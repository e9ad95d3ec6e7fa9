#include "framework/cluster/input_agreement.hpp"

#include <mpi.h>

#include <algorithm>
#include <cstdint>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

#include "framework/cluster/cluster.hpp"
#include "framework/cluster/run_fingerprint.hpp"
#include "framework/core/error.hpp"

namespace hystbench::cluster {
namespace {

struct RankState {
  std::uint64_t exit_code;  // 0: inputs read
  std::uint64_t fingerprint;
};

bool agreed = false;

std::vector<RankState> exchange(RankState mine) {
  std::vector<RankState> all(static_cast<std::size_t>(size()));
  MPI_Allgather(&mine, 2, MPI_UINT64_T, all.data(), 2, MPI_UINT64_T, MPI_COMM_WORLD);
  agreed = true;
  return all;
}

}  // namespace

void agree_inputs_read(const Experiment& experiment, const Problem& problem) {
  const auto all = exchange({0, run_fingerprint(experiment, problem)});
  std::uint64_t worst = 0;
  for (const auto& s : all) worst = std::max(worst, s.exit_code);
  // The ranks that failed print why; this one only stops.
  if (worst != 0) throw RankStopped{static_cast<int>(worst)};
  for (std::size_t k = 1; k < all.size(); ++k) {
    if (all[k].fingerprint == all[0].fingerprint) continue;
    if (rank() != 0) throw RankStopped{2};
    throw InputError("rank " + std::to_string(k) + " read a different experiment or data than "
                     "rank 0: give every rank the same experiment file, options and data files");
  }
}

void agree_inputs_failed(int exit_code) {
  const auto all = exchange({static_cast<std::uint64_t>(exit_code), 0});
  if (rank() != 0 && all[0].exit_code != 0)
    throw RankStopped{static_cast<int>(all[0].exit_code)};
}

bool inputs_agreed() { return agreed; }

// Lives here because it is the failure half of the agreement.
void run_on_all_ranks(const std::function<void()>& body) {
  if (size() == 1) return body();
  const std::string prefix = "rank " + std::to_string(rank()) + ": ";
  try {
    body();
  } catch (const InputError& e) {
    if (inputs_agreed()) throw;
    agree_inputs_failed(2);
    if (rank() == 0) throw;
    throw InputError(prefix + e.what());
  } catch (const std::exception& e) {
    if (inputs_agreed()) throw;
    agree_inputs_failed(1);
    if (rank() == 0) throw;
    throw std::runtime_error(prefix + e.what());
  }
}

}  // namespace hystbench::cluster
