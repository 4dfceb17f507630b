#pragma once
// Checkpoints: every particle field plus run metadata in one HDF5 file, for exact restarts.
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>

#include "core/particles.hpp"
#include "parallel/comm.hpp"

namespace monosph {

struct CheckpointMeta {
  double time = 0;
  long step = 0;
  double dt = 0;
  std::string scene_yaml;
  std::int64_t next_id = 0;
  std::map<std::string, double> scalars;  // module state (rigid bodies, counters...)
};

// Writes file atomically (temporary + rename). Stores every field of p as /fields/<name>
// (n x ncomp, double or int64, attributes ncomp and output) and meta under /meta. The next_id
// stored is max(meta.next_id, p.next_id()). Every dataset is chunked with a Fletcher32 checksum.
// Throws OutputError ("output: cannot write FILE: reason") if the file cannot be written.
template <int D>
void write_checkpoint(const std::filesystem::path& file, const Particles<D>& p,
                      const CheckpointMeta& meta);

// MPI: the first `owned` particles of every rank, in rank order, into one file that a run on any
// number of ranks restarts from; the ranks write their rows in turn (no rank holds more than
// its own). Collective; the same as above on one rank.
template <int D>
void write_checkpoint(const std::filesystem::path& file, const Particles<D>& p, std::size_t owned,
                      const CheckpointMeta& meta, const Comm& comm);

// Restores every field of p exactly (registering missing fields, resizing p, setting next_id)
// and returns the metadata. Throws InputError naming the file if it is missing, not a monosph
// checkpoint, damaged (a checksum fails, a dataset is missing, a real value is not finite, ids
// out of range: check_checkpoint_data), or written with another dimension. On error p is left
// unchanged. Checkpoints written before the checksums were added read as before.
// With parts > 1 only the rows [n part / parts, n (part + 1) / parts) are read (MPI: each rank
// reads its share of the file).
template <int D>
CheckpointMeta read_checkpoint(const std::filesystem::path& file, Particles<D>& p, int part = 0,
                               int parts = 1);

// The dimension (2 or 3) a checkpoint was written with; same errors as read_checkpoint.
int checkpoint_dimension(const std::filesystem::path& file);

}  // namespace monosph
