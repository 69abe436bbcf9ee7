#pragma once

#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include <cairn/planning/locomotion/transition_oracle.h>

namespace cairn::planning {

/// Builds a TransitionOracle in checkpointed pieces that any number of processes share (thesis 2.3.3 built its
/// oracles from about 12,600 simulated patterns over two days: a build of that size must survive being killed
/// and must spread over a cluster).
///
/// The grid's displacement cells are cut into chunks of `cells_per_chunk` consecutive cells; chunk k is
/// computed by rank k mod num_ranks (TransitionOracle::BuildCells) and written atomically into the checkpoint
/// folder as `chunk-<k>.bin`: a text header (magic "cairn-oracle-chunk 1", the build key, the chunk's first cell
/// and cell count, the payload size and checksum) and the entries as TransitionOracle stores them. A chunk whose
/// file is already there and valid for this build (same TransitionOracle::BuildKey, same cells, checksum) is not
/// computed again, so a killed build resumes where it stopped; a file of another build, or a corrupt one, is
/// recomputed and replaced. Merge reads every chunk and assembles the table (TransitionOracle::FromEntries).
///
/// Determinism: chunks do not depend on the number of ranks or threads, and every cell is computed
/// independently of the others, so the merged table is the same, byte for byte, whatever the number of ranks,
/// and the same as TransitionOracle::Build's.
///
/// Thread/process safety: ranks write disjoint chunk files, each atomically (a rename), so concurrent ranks on
/// one shared folder never see a half-written chunk; Merge must run after every rank has finished (a barrier).
class OracleShardBuilder {
 public:
  /// Most cells a chunk may hold, and most chunks a build may have.
  static constexpr int kMaxCellsPerChunk = 100000;
  static constexpr std::size_t kMaxChunks = 1000000;

  /// What BuildShard did.
  struct ShardReport {
    int computed{0};  ///< chunks computed (and written) by this call
    int resumed{0};   ///< chunks of this rank already present and valid, skipped
    int replaced{0};  ///< of `computed`: chunks whose existing file was stale or corrupt
  };

  /// Throws std::invalid_argument for a grid that does not fit the model's reach, cells_per_chunk outside
  /// [1, kMaxCellsPerChunk], more than kMaxChunks chunks, or an empty checkpoint folder name. The model must
  /// outlive the builder. `source` gives the entries (null: the analytic model); it is part of the build key, and
  /// BuildShard uses it whatever its options say.
  OracleShardBuilder(const WalkingModel& model, WalkingObjective objective, OracleGrid grid,
                     std::string checkpoint_folder, int cells_per_chunk = 16,
                     std::shared_ptr<const TransitionSource> source = nullptr);

  /// Number of chunks of the build.
  int num_chunks() const { return num_chunks_; }
  /// The chunks rank `rank` of `num_ranks` computes, ascending.
  std::vector<int> ChunksOfRank(int rank, int num_ranks) const;
  /// The checkpoint file of chunk k.
  std::string ChunkPath(int chunk) const;

  /// Computes the missing chunks of rank `rank` of `num_ranks` (creating the checkpoint folder), one line per
  /// chunk to `log` when not null. options.progress counts the entries of all this rank's chunks (resumed ones
  /// at once). Throws std::invalid_argument for num_ranks < 1 or rank outside [0, num_ranks),
  /// std::runtime_error when the folder or a chunk cannot be written (naming it).
  ShardReport BuildShard(int rank, int num_ranks, const OracleBuildOptions& options = OracleBuildOptions(),
                         std::ostream* log = nullptr) const;

  /// Chunks without a valid checkpoint file, ascending.
  std::vector<int> MissingChunks() const;

  /// The table from every chunk. Throws std::runtime_error naming the missing or invalid chunks (the first few)
  /// and how many there are when any chunk is not there or not valid for this build.
  TransitionOracle Merge() const;

  /// Removes the chunk files of this build (and temporary files of chunks whose write was interrupted) and the
  /// folder when it is left empty (after a successful Merge and Save); other files in the folder are kept. Never throws: a chunk left behind only costs disk space.
  void RemoveCheckpoints() const;

 private:
  // The entries of chunk k if its file is valid for this build; false otherwise (`why` says what is wrong, ""
  // for a missing file).
  bool ReadChunk(int chunk, std::vector<TransitionOracle::Entry>* entries, std::string* why) const;
  std::size_t FirstCell(int chunk) const;
  std::size_t CellsIn(int chunk) const;

  const WalkingModel* model_;
  WalkingObjective objective_;
  OracleGrid grid_;
  std::string folder_;
  int cells_per_chunk_;
  int num_chunks_{0};
  std::uint64_t key_{0};
  std::shared_ptr<const TransitionSource> source_;
};

}  // namespace cairn::planning
