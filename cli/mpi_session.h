#pragma once

/// @file
/// The MPI world of one `cairn` process, for subcommands that spread work over ranks (`oracle build`).

namespace cairn::cli {

/// Rank and size of the MPI world when the process was started by an MPI launcher (`mpirun -np N cairn ...`), or
/// rank 0 of 1 otherwise. MPI is initialised only under a launcher (Open MPI sets OMPI_COMM_WORLD_SIZE, PMIx
/// PMIX_RANK): a plain `cairn` never starts MPI, whose singleton start-up would launch a daemon and read the
/// network configuration for a single process. One session per process, created by the subcommand that needs
/// it; the destructor finalises MPI.
///
/// Collective calls (Sum) must be made by every rank in the same order, as MPI requires.
class MpiSession {
 public:
  /// Initialises MPI when launched by mpirun. Throws std::runtime_error if MPI fails to start or was already
  /// started in this process.
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  /// This process's rank, in [0, size()).
  int rank() const { return rank_; }
  /// Number of ranks (1 without a launcher).
  int size() const { return size_; }
  /// True when MPI was initialised (started by a launcher).
  bool active() const { return active_; }

  /// The sum of `value` over the ranks (every rank learns it).
  int Sum(int value) const;

 private:
  bool active_{false};
  int rank_{0};
  int size_{1};
};

}  // namespace cairn::cli
