#include "mpi_session.h"

#include <cstdlib>
#include <stdexcept>

#include <mpi.h>

namespace cairn::cli {

MpiSession::MpiSession() {
  if (std::getenv("OMPI_COMM_WORLD_SIZE") == nullptr && std::getenv("PMIX_RANK") == nullptr) return;
  int initialised = 0;
  MPI_Initialized(&initialised);
  if (initialised != 0) throw std::runtime_error("MPI was already initialised in this process");
  if (MPI_Init(nullptr, nullptr) != MPI_SUCCESS) {
    throw std::runtime_error("MPI failed to start; check the mpirun command line");
  }
  active_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiSession::~MpiSession() {
  if (active_) MPI_Finalize();
}

int MpiSession::Sum(int value) const {
  if (!active_) return value;
  int total = 0;
  MPI_Allreduce(&value, &total, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  return total;
}

}  // namespace cairn::cli
