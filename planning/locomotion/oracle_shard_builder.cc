#include "cairn/planning/locomotion/oracle_shard_builder.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <system_error>
#include <utility>

#include "cairn/common/atomic_file.h"
#include "cairn/common/hash.h"
#include "cairn/common/number_text.h"

namespace cairn::planning {
namespace {

constexpr const char* kChunkMagic = "cairn-oracle-chunk 1";
// Chunk files are the header (a few lines) plus 72 bytes per entry; anything far larger is not one of ours.
constexpr std::size_t kMaxHeaderLine = 200;

std::string ChunkName(int chunk) {
  std::string digits = FormatShort(chunk);
  if (digits.size() < 6) digits.insert(0, 6 - digits.size(), '0');
  return "chunk-" + digits + ".bin";
}

}  // namespace

OracleShardBuilder::OracleShardBuilder(const WalkingModel& model, WalkingObjective objective, OracleGrid grid,
                                       std::string checkpoint_folder, int cells_per_chunk,
                                       std::shared_ptr<const TransitionSource> source)
    : model_(&model),
      objective_(objective),
      grid_(std::move(grid)),
      folder_(std::move(checkpoint_folder)),
      cells_per_chunk_(cells_per_chunk),
      source_(std::move(source)) {
  grid_.Validate(model.reach());
  if (folder_.empty()) throw std::invalid_argument("OracleShardBuilder: the checkpoint folder name is empty");
  if (cells_per_chunk < 1 || cells_per_chunk > kMaxCellsPerChunk) {
    throw std::invalid_argument("OracleShardBuilder: cells_per_chunk is " + FormatShort(cells_per_chunk) +
                                "; give a count in [1, " + FormatShort(kMaxCellsPerChunk) + "]");
  }
  const std::size_t cells = grid_.num_displacements();
  const std::size_t chunks = (cells + static_cast<std::size_t>(cells_per_chunk) - 1) / static_cast<std::size_t>(cells_per_chunk);
  if (chunks > kMaxChunks) {
    throw std::invalid_argument("OracleShardBuilder: " + FormatShort(cells) + " cells in chunks of " +
                                FormatShort(cells_per_chunk) + " make " + FormatShort(chunks) +
                                " chunks, more than the limit of " + FormatShort(kMaxChunks) +
                                "; use larger chunks");
  }
  num_chunks_ = static_cast<int>(chunks);
  key_ = TransitionOracle::BuildKey(model, objective, grid_, source_.get());
}

std::size_t OracleShardBuilder::FirstCell(int chunk) const {
  return static_cast<std::size_t>(chunk) * static_cast<std::size_t>(cells_per_chunk_);
}

std::size_t OracleShardBuilder::CellsIn(int chunk) const {
  return std::min(static_cast<std::size_t>(cells_per_chunk_), grid_.num_displacements() - FirstCell(chunk));
}

std::vector<int> OracleShardBuilder::ChunksOfRank(int rank, int num_ranks) const {
  if (num_ranks < 1) {
    throw std::invalid_argument("OracleShardBuilder: num_ranks is " + FormatShort(num_ranks) + "; give at least 1");
  }
  if (rank < 0 || rank >= num_ranks) {
    throw std::invalid_argument("OracleShardBuilder: rank " + FormatShort(rank) + " is outside [0, " +
                                FormatShort(num_ranks) + ")");
  }
  std::vector<int> chunks;
  for (int k = rank; k < num_chunks_; k += num_ranks) chunks.push_back(k);
  return chunks;
}

std::string OracleShardBuilder::ChunkPath(int chunk) const {
  return (std::filesystem::path(folder_) / ChunkName(chunk)).string();
}

bool OracleShardBuilder::ReadChunk(int chunk, std::vector<TransitionOracle::Entry>* entries, std::string* why) const {
  why->clear();
  const std::string path = ChunkPath(chunk);
  std::error_code error;
  const std::size_t expected_payload = CellsIn(chunk) * grid_.mu.size() * TransitionOracle::kBytesPerEntry;
  const auto size = std::filesystem::file_size(path, error);
  if (error) return false;  // missing
  if (size > expected_payload + 10 * kMaxHeaderLine) {
    *why = "too large for this build's chunk";
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    *why = "cannot be opened";
    return false;
  }
  std::ostringstream buffer;
  buffer << in.rdbuf();
  const std::string bytes = buffer.str();
  std::size_t position = 0;
  auto line = [&](std::string* out) {
    const std::size_t end = bytes.find('\n', position);
    if (end == std::string::npos || end - position > kMaxHeaderLine) return false;
    *out = bytes.substr(position, end - position);
    position = end + 1;
    return true;
  };
  std::string magic, key, first, cells, payload_bytes, checksum, end;
  if (!line(&magic) || magic != kChunkMagic || !line(&key) || !line(&first) || !line(&cells) ||
      !line(&payload_bytes) || !line(&checksum) || !line(&end) || end != "end") {
    *why = "has a corrupt header";
    return false;
  }
  if (key != "key " + HashHex(key_)) {
    *why = "belongs to another build (robot, objective, source or grid)";
    return false;
  }
  if (first != "first_cell " + FormatShort(FirstCell(chunk)) || cells != "cells " + FormatShort(CellsIn(chunk))) {
    *why = "covers other cells (another chunk size)";
    return false;
  }
  const std::string_view payload = std::string_view(bytes).substr(position);
  if (payload_bytes != "payload_bytes " + FormatShort(expected_payload) || payload.size() != expected_payload) {
    *why = "is truncated";
    return false;
  }
  if (checksum != "checksum " + HashHex(Fnv1a64(payload))) {
    *why = "fails its checksum";
    return false;
  }
  *entries = TransitionOracle::DecodeEntries(payload, CellsIn(chunk) * grid_.mu.size());
  return true;
}

OracleShardBuilder::ShardReport OracleShardBuilder::BuildShard(int rank, int num_ranks,
                                                               const OracleBuildOptions& options,
                                                               std::ostream* log) const {
  const std::vector<int> chunks = ChunksOfRank(rank, num_ranks);
  std::error_code error;
  std::filesystem::create_directories(folder_, error);
  if (error) {
    throw std::runtime_error("OracleShardBuilder: cannot create the checkpoint folder '" + folder_ + "' (" +
                             error.message() + "); choose a writable folder");
  }
  ShardReport report;
  std::vector<TransitionOracle::Entry> entries;
  // Progress over the rank's chunks: entries of the chunks before this one plus this one's.
  std::size_t total = 0, finished = 0;
  for (const int chunk : chunks) total += CellsIn(chunk) * grid_.mu.size();
  OracleBuildOptions chunk_options = options;
  chunk_options.source = source_;
  if (options.progress) {
    chunk_options.progress = [&](std::size_t done, std::size_t) { options.progress(finished + done, total); };
  }
  for (const int chunk : chunks) {
    std::string why;
    const std::size_t chunk_entries = CellsIn(chunk) * grid_.mu.size();
    if (ReadChunk(chunk, &entries, &why)) {
      ++report.resumed;
      finished += chunk_entries;
      if (options.progress) options.progress(finished, total);
      continue;
    }
    if (!why.empty()) ++report.replaced;
    entries = TransitionOracle::BuildCells(*model_, objective_, grid_, FirstCell(chunk), CellsIn(chunk), chunk_options);
    finished += chunk_entries;
    const std::string payload = TransitionOracle::EncodeEntries(entries);
    std::string header = std::string(kChunkMagic) + "\n";
    header += "key " + HashHex(key_) + "\n";
    header += "first_cell " + FormatShort(FirstCell(chunk)) + "\n";
    header += "cells " + FormatShort(CellsIn(chunk)) + "\n";
    header += "payload_bytes " + FormatShort(payload.size()) + "\n";
    header += "checksum " + HashHex(Fnv1a64(payload)) + "\n";
    header += "end\n";
    WriteFileAtomically(ChunkPath(chunk), header + payload);
    ++report.computed;
    if (log != nullptr) {
      *log << "rank " << rank << "/" << num_ranks << ": chunk " << chunk + 1 << " of " << num_chunks_
           << (why.empty() ? "" : " (replaced: the old file " + why + ")") << "\n";
    }
  }
  return report;
}

std::vector<int> OracleShardBuilder::MissingChunks() const {
  std::vector<int> missing;
  std::vector<TransitionOracle::Entry> entries;
  std::string why;
  for (int k = 0; k < num_chunks_; ++k) {
    if (!ReadChunk(k, &entries, &why)) missing.push_back(k);
  }
  return missing;
}

TransitionOracle OracleShardBuilder::Merge() const {
  std::vector<TransitionOracle::Entry> all;
  all.reserve(grid_.num_entries());
  std::vector<std::string> problems;
  int bad = 0;
  std::vector<TransitionOracle::Entry> entries;
  for (int k = 0; k < num_chunks_; ++k) {
    std::string why;
    if (!ReadChunk(k, &entries, &why)) {
      if (++bad <= 3) problems.push_back(ChunkPath(k) + (why.empty() ? " is missing" : " " + why));
      continue;
    }
    all.insert(all.end(), entries.begin(), entries.end());
  }
  if (bad > 0) {
    std::string list;
    for (const std::string& p : problems) list += (list.empty() ? "" : "; ") + p;
    throw std::runtime_error("OracleShardBuilder: " + FormatShort(bad) + " of " + FormatShort(num_chunks_) +
                             " chunks are not ready (" + list + (bad > 3 ? "; ..." : "") +
                             "); run the build again to compute them");
  }
  return TransitionOracle::FromEntries(*model_, objective_, grid_, std::move(all), source_.get());
}

void OracleShardBuilder::RemoveCheckpoints() const {
  std::error_code error;
  for (int k = 0; k < num_chunks_; ++k) std::filesystem::remove(ChunkPath(k), error);
  // A rank killed while writing a chunk leaves WriteFileAtomically's temporary file, named after the chunk
  // file with ".tmp." and a random suffix appended.
  std::vector<std::filesystem::path> leftovers;
  for (std::filesystem::directory_iterator it(folder_, error), end; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (name.rfind("chunk-", 0) == 0 && name.find(".bin.tmp.") != std::string::npos) leftovers.push_back(it->path());
  }
  for (const std::filesystem::path& path : leftovers) std::filesystem::remove(path, error);
  if (std::filesystem::is_empty(folder_, error) && !error) std::filesystem::remove(folder_, error);
}

}  // namespace cairn::planning
