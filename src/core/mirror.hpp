#pragma once
// Mirror<D>: symmetry planes at faces of the domain (`domain.mirror`), by mirror ghost particles
// (the ghost-particle symmetry boundary of Libersky, Petschek, Carney, Hipp & Allahdadi 1993,
// J. Comput. Phys. 109, 67-75, "High strain Lagrangian hydrodynamics"). At every neighbour
// rebuild each particle within `halo` of a plane gets an image: position reflected across the
// plane, vectors with the normal component negated, DxD tensors reflected as R T R (R the
// reflection: entry (a, b) times s_a s_b), scalars and integers copied. A particle near two planes
// of different axes also gets the image across both (quarter models). Like MPI ghosts
// (Decomposition), images come after the owned particles, have no neighbour list and are
// refreshed by exchange() from their sources after every pass that writes a field read through
// neighbours; they kick and drift with their sources' mirrored accelerations.
//
// The image of a body symmetric about the plane is the body's other half, so the half model gives
// the full model's result (tests/unit/test_mirror.cpp). Serial only (one MPI rank). Total-
// Lagrangian bodies hold their own images in their reference pairs (solid/total_lagrangian.hpp).
#include <span>
#include <string>
#include <vector>

#include "core/neighbours.hpp"
#include "core/particles.hpp"

namespace monosph {

template <int D>
class Mirror {
 public:
  // lo[a] / hi[a]: a plane at dom.lo[a] / dom.hi[a]; halo: width of the ghost layer.
  Mirror(const Domain<D>& dom, std::vector<bool> lo, std::vector<bool> hi, double halo);

  // The neighbour domain: the scene domain extended by the halo beyond every mirror plane, so
  // that the images lie inside it.
  Domain<D> extended(const Domain<D>& dom) const;
  // p holds owned particles only: a particle beyond a plane is replaced by its image, then the
  // images of all particles within the halo of a plane are appended (all fields).
  void make_ghosts(Particles<D>& p);
  // Refreshes the images' values of the given fields from their sources.
  void exchange(Particles<D>& p, std::span<const int> fields) const;
  // Drops the images (p then holds the owned particles only).
  void drop(Particles<D>& p) const { p.resize(owned_); }
  void adopt(const Particles<D>& p) { owned_ = p.size(), src_.clear(), sign_.clear(); }
  std::size_t owned() const { return owned_; }
  std::size_t ghosts() const { return src_.size(); }

 private:
  void reflect(Field& f, const std::string& name) const;
  void put_back(Particles<D>& p) const;  // particles beyond a plane replaced by their images
  std::vector<double> lo_, hi_;          // plane coordinate per axis (NaN: none)
  double halo_;
  std::size_t owned_ = 0;
  std::vector<int> src_;        // per image: its source particle
  std::vector<Vec<D>> sign_;    // per image: s_a = -1 on reflected axes, else 1
  std::vector<Vec<D>> offset_;  // per image: 2 c_a on reflected axes (x' = offset + s x)
};

// Fields holding positions (reflected as points, x' = 2c - x, not as vectors).
bool mirror_point_field(const std::string& name);

}  // namespace monosph
