#pragma once
// Decomposition<D>: the particles of an Open MPI run split into one region per rank by
// recursive coordinate bisection on particle counts (Zoltan RCB), plus a ghost layer of width
// support + skin. Locally, particles [0, owned) are this rank's and [owned, size) are ghost
// copies of other ranks' particles, stored at their own (wrapped) positions: the periodic cell
// list finds them across periodic borders exactly as in a serial run.
//
// Migration and ghost creation happen at neighbour rebuilds (all fields travel); between
// rebuilds exchange() refreshes only the fields a pass has just written.
#include <memory>
#include <span>
#include <vector>

#include "core/neighbours.hpp"
#include "core/particles.hpp"
#include "parallel/comm.hpp"

struct Zoltan_Struct;

namespace monosph {

struct MpiRequests;  // std::vector<MPI_Request> (decomposition.cpp): <mpi.h> stays out

struct DecompositionStats {
  long rebalances = 0, migrated = 0;  // partitions computed, particles that changed rank
  long exchanges = 0;                 // calls of exchange() (halo refreshes)
  long peers = 0;                     // ranks exchanged with (last rebuild)
  double halo_bytes = 0;              // bytes sent by exchange() on this rank (cumulative)
  double exchange_seconds = 0, rebuild_seconds = 0;
  double wait_seconds = 0;
  double imbalance = 1;  // largest / mean work at the last rebuild, before re-partitioning  // in
                         // MPI waits of both: transfer plus waiting for slower ranks
};

template <int D>
class Decomposition {
 public:
  // imbalance: largest / mean owned count that triggers a new partition at a rebuild.
  Decomposition(const Comm& comm, const Domain<D>& dom, double halo, double imbalance = 1.05);
  ~Decomposition();
  Decomposition(const Decomposition&) = delete;
  Decomposition& operator=(const Decomposition&) = delete;

  // Every rank holds a disjoint part of the particles (a fresh start): all of them are owned.
  void adopt(Particles<D>& p) { owned_ = p.size(), ghosts_ = 0; }
  // p holds owned particles only (wrapped), work their costs: a new partition when the largest
  // rank's work passes `imbalance` x the mean, then particles move to the rank whose region
  // contains them.
  void migrate(Particles<D>& p, const std::vector<float>& work);
  // Appends the ghost copies (all fields) that this rank needs; records the exchange lists.
  void make_ghosts(Particles<D>& p);
  // Refreshes the ghost values of the given fields from their owners.
  void exchange(Particles<D>& p, std::span<const int> fields);
  std::size_t owned() const { return owned_; }
  std::size_t ghosts() const { return ghosts_; }
  const DecompositionStats& stats() const { return stats_; }

 private:
  void partition(Particles<D>& p, const std::vector<float>& work);
  const Comm& comm_;
  Domain<D> dom_;
  double halo_, imbalance_;
  Zoltan_Struct* zz_ = nullptr;
  bool have_cuts_ = false;
  std::size_t owned_ = 0, ghosts_ = 0;
  std::vector<int> peers_;                            // ranks this one exchanges ghosts with
  std::vector<std::vector<int>> send_;                // per peer: local indices sent
  std::vector<std::size_t> recv_first_, recv_count_;  // per peer: ghost range
  std::vector<std::vector<char>> sbuf_, rbuf_;
  std::unique_ptr<MpiRequests> req_;
  DecompositionStats stats_;
};

}  // namespace monosph
