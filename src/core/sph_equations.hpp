#pragma once
// The Eulerian SPH equations every phase shares (Mohseni-Mofidi & Bierwisch 2020, "MMB"):
// Shepard sum and correction matrix (Eq. 7-10), velocity gradient (Eq. 16), continuity and
// momentum (Eq. 11) with Sigma = -p I + S (Eq. 12), linear EOS (Eq. 13), artificial viscosity
// (Eq. 17-18). Particles interact here if both are fluid, or both belong to the same solid body
// (fluids move to the delta-plus FluidModule when a scene has one: set_solids_only).
#include "core/simulation.hpp"

namespace monosph {

template <int D>
class SphEquations : public Module<D> {
 public:
  // store_velocity_gradient: keep grad v as a field (solid modules read it).
  explicit SphEquations(Simulation<D>& sim, bool store_velocity_gradient = false);
  std::string name() const override { return "sph"; }
  bool fast() const override { return solids_only_; }
  void sums(Simulation<D>& sim) override;
  void rates(Simulation<D>& sim) override;
  void constitutive(Simulation<D>& sim) override;
  void forces(Simulation<D>& sim) override;
  double max_dt(Simulation<D>& sim) override;
  bool reads_pair_rows(int body) const override {
    return !skip(body) && (!solids_only_ || solid_[body]);
  }
  // With the fluid module on, fluid and wall particles are its business: only solids here.
  void set_solids_only(bool on) { solids_only_ = on; }

 private:
  bool solids_only_ = false;
  // Per body: total-Lagrangian (Ganzenmueller 2015): its particles are skipped by every pass here
  // (SolidModule computes their F, density, stress and forces from the reference configuration).
  std::vector<char> tl_, solid_;  // per body
  bool skip(std::int64_t body) const { return tl_[body] != 0; }
  int kshep_, kcorr_, kgradv_ = -1, kstress_ = -1, kas_ = -1;
  bool any_av_ = false, any_diffusion_ = false;
  // Per-particle scratch of the pair passes (stress factor, AV and diffusion parameters).
  std::vector<double> wpair_, cs_, alpha_, beta_, delta_, phimax_;
  std::vector<Mat<D>> sig_;
};

// Correction matrix L_i = [sum_j V_j (x_j - x_i) (x) grad_i W_ij]^-1 (MMB Eq. 9). Directions with
// too little support (eigenvalue < 0.02 of a full one) are left uncorrected.
template <int D>
Mat<D> invert_correction(const Mat<D>& b);

}  // namespace monosph
