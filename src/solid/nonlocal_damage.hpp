#pragma once
// Non-local damage (issue 51): the Johnson-Cook damage increment of a particle is replaced by the
// weighted average of its neighbours' increments within a fixed physical length l, so that the
// width of a failing zone, and the energy spent to fail it, no longer scale with dp
// (Pijaudier-Cabot & Bazant 1987, J. Eng. Mech. 113:1512; averaging the damage rate as Tvergaard
// & Needleman 1995, Int. J. Solids Struct. 32:1063; docs/theory.md, "Non-local damage").
#include <span>
#include <vector>

#include "core/simulation.hpp"

namespace monosph {

// Bell-shaped weight of Bazant & Jirasek 2002 (J. Eng. Mech. 128:1119, Eq. 8): (1 - r^2/l^2)^2
// for r < l, else 0.
inline double bell_weight(double r2, double l2) {
  if (r2 >= l2) return 0.0;
  const double q = 1.0 - r2 / l2;
  return q * q;
}

template <int D>
class NonlocalAverage {
 public:
  // out_i = sum_j w(r_ij, l_i) V_j inc_j / sum_j w(r_ij, l_i) V_j over the owned particles j of
  // i's body (minimum image along periodic axes), for every owned i with length[i] > 0; out_i = 0
  // for the others and where no neighbour within l_i has an increment.
  void average(Simulation<D>& sim, std::span<const double> length, std::span<const double> inc,
               std::vector<double>& out);

 private:
  void bin(Simulation<D>& sim, std::span<const double> length, double cell);
  std::array<int, D> nc_{};                // cells per axis
  Vec<D> size_, lo_;                       // cell size, origin of the first cell
  std::vector<std::size_t> start_, fill_;  // first item of each cell
  std::vector<int> items_, cell_of_;    // particles by cell; the cell of each particle (-1: none)
  std::vector<std::size_t> act_start_;  // per cell, its particles with a positive increment
  std::vector<int> act_items_;
};

}  // namespace monosph
