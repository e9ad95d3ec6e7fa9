// Rank and size of this process under MPI (the MPI build).
#include <mpi.h>

#include <cstdio>
#include <cstdlib>

#include "framework/cluster/cluster.hpp"

namespace hystbench::cluster {
namespace {

int this_rank = 0;
int ranks = 1;
bool started = false;

// MPI starts only under a launcher (mpirun, mpiexec, srun), so the MPI build
// runs every other command, and `run` on a workstation, as a plain program
// (no singleton start-up, no warnings of the MPI library).
bool started_by_launcher() {
  for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
    if (std::getenv(variable) != nullptr) return true;
  return false;
}

}  // namespace

Session::Session(int& argc, char**& argv) {
  if (!started_by_launcher()) return;
  // Serialized: on every rank the OpenMP threads that finish trials send
  // them, one at a time; on rank 0 a second thread serves the other ranks.
  int provided = MPI_THREAD_SINGLE;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_SERIALIZED, &provided);
  started = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &this_rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  if (provided < MPI_THREAD_SERIALIZED && ranks > 1) {
    if (this_rank == 0)
      std::fprintf(stderr, "hystbench: error: this MPI library does not provide "
                           "MPI_THREAD_SERIALIZED, which a run over several ranks needs\n");
    MPI_Finalize();
    std::exit(1);
  }
}

Session::~Session() {
  if (started) MPI_Finalize();
}

int rank() { return this_rank; }
int size() { return ranks; }

}  // namespace hystbench::cluster
