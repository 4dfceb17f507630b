#pragma once
// Total-Lagrangian SPH solids (Ganzenmueller 2015, "G15", Sect. 2-3), per body with
// `formulation: total_lagrangian`. The reference configuration is the initial one: reference
// neighbours (same body, within the kernel support at the initial positions) and the corrected
// reference kernel gradients g_ij = V0_j L_i grad W(X_ij) (G15 Eq. 14-16) are found once and never
// change. Deformation gradient F (G15 Eq. 17), density rho0/det F, velocity gradient Fdot F^-1,
// PK1 stress from the hypoelastic (Jaumann S + EOS pressure, J2/Johnson-Cook) or neo-Hookean
// (G15 Eq. 44) model, the momentum-conserving corrected force (G15 Eq. 24) and the hourglass
// force (G15 Eq. 25-32). SolidModule owns it and calls it from its passes.
//
// Storage is in "slots": the total-Lagrangian particles in the order of their ids. Reference
// data is per slot and survives the cell-order re-sorting of particles; only the slot -> index
// map is renewed at every neighbour rebuild. Restarts rebuild the reference data from the
// checkpointed fields initial_position and reference_volume (deterministic: bit-identical).
// Symmetry planes (domain.mirror): a particle's reference neighbours include the images of the
// particles near a plane; an image's position, velocity, F and P follow from its source's by the
// reflection, so no image particle is needed (the Mirror's images serve the other modules).
#include <array>
#include <span>
#include <vector>

#include "core/simulation.hpp"
#include "solid/solid_keys.hpp"
#include "solid/solid_material.hpp"

namespace monosph {

template <int D>
class TotalLagrangian {
 public:
  // Field indices of SolidModule: deviatoric stress, deformation gradient, velocity gradient,
  // initial position (= reference position), plastic strain and yield stress (-1 if none).
  TotalLagrangian(Simulation<D>& sim, int kS, int kF, int kgradv, int kX0, int kep, int ksy);

  bool is_tl(std::int64_t body) const { return tlb_[body] != 0; }
  void on_create(Simulation<D>& sim);  // reference volumes V0 = m / rho
  void on_rebuild(Simulation<D>& sim);
  void restarted(Simulation<D>& sim);  // F at the checkpoint's positions
  // L = Fdot F^-1 at the half-step velocities, with the F of the last sums (the positions have
  // not moved since: the drift follows the rates).
  void rates(Simulation<D>& sim);
  void sums(Simulation<D>& sim);          // F (G15 Eq. 17) and rho = rho0 / det F
  void constitutive(Simulation<D>& sim);  // pressure, S (neo-Hookean) and PK1 P
  // Internal and hourglass forces; omega2 (per particle) the hourglass spring frequency bound,
  // hge (may be empty) the energy in the hourglass springs.
  void forces(Simulation<D>& sim, std::vector<double>& omega2, std::span<double> hge);

  // Reference pair data of a particle (tests): number of reference neighbours.
  std::size_t reference_neighbours(std::size_t i) const;

 private:
  std::vector<SolidBodyKeys> keys_;  // per body (solid_keys.hpp)
  std::vector<char> neo_hookean_;    // per material (solid_material.hpp)
  void build(Simulation<D>& sim);    // the reference pairs, once
  void map_slots(Simulation<D>& sim);
  // sum_j (f_j - f_i) (x) g_ij over the reference pairs of slot s (G15 Eq. 17 for f = x); f a
  // point field (positions: images reflected across the planes) or a vector field (velocities).
  Mat<D> reference_gradient(std::size_t s, std::span<const Vec<D>> f, bool point) const {
    const int i = idx_[s];
    Mat<D> G = Mat<D>::Zero();
    for (std::size_t k = start_[s]; k < start_[s + 1]; ++k) {
      const Vec<D>& fj = f[idx_[nj_[k]]];
      G.noalias() += ((mask_[k] ? image(fj, mask_[k], point) : fj) - f[i]) * g_[k].transpose();
    }
    return G;
  }
  // Mirror image across the planes of the axes in `m` (bit a: axis a): a point is reflected
  // (x_a -> 2 c_a - x_a), a vector has those components negated.
  Vec<D> image(Vec<D> f, unsigned m, bool point) const {
    for (int a = 0; a < D; ++a)
      if (m >> a & 1u) f[a] = (point ? 2 * plane_[a] : 0.0) - f[a];
    return f;
  }
  // R M R for the reflection R of the axes in m: entry (a, b) times s_a s_b.
  Mat<D> image(Mat<D> M, unsigned m) const {
    for (int a = 0; a < D; ++a)
      for (int b = 0; b < D; ++b)
        if ((m >> a & 1u) != (m >> b & 1u)) M(a, b) = -M(a, b);
    return M;
  }

  std::vector<char> tlb_;  // per body
  int kS_, kF_, kgradv_, kX0_, kV0_, kep_, ksy_;
  // Per slot: particle id, current index, V0, F, V0 times PK1 P, hourglass stiffness (G15 Eq. 32).
  std::vector<std::int64_t> sid_;
  std::vector<int> idx_;
  std::vector<double> v0_;
  std::vector<Mat<D>> F_, P_;
  std::vector<double> E_;
  // Reference pairs of slot s: k in [start_[s], start_[s+1]): neighbour slot, X_ij = X_j - X_i,
  // W(|X_ij|) / X_ij^2, g_ij and g_ji (of the pair (j, i) in j's list).
  // mask_: 0 for a neighbour itself, else the axes across whose symmetry planes (domain.mirror)
  // the neighbour is the image of slot nj_ (Libersky et al. 1993 ghosts, built in the reference
  // configuration: the full body's reference neighbours and corrections).
  std::vector<std::size_t> start_;
  std::vector<int> nj_;
  std::vector<unsigned char> mask_;
  std::array<double, D> plane_;     // symmetry plane per axis (NaN: none)
  std::vector<Vec<D>> X_, g_, gr_;  // gr_: g_ji
  std::vector<double> w_;           // W(X_ij) / X_ij^2
  std::vector<int> slot_of_;        // per particle index: slot or -1
  std::vector<int> pos_;            // scratch of map_slots: particle id -> index
  bool built_ = false;
};

}  // namespace monosph
