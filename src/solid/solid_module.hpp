#pragma once
// Hourglass-controlled Eulerian SPH solids (Mohseni-Mofidi & Bierwisch 2020, "MMB", Sect. 2).
// Jaumann-rate hypoelasticity (Eq. 14-16, objective Hughes-Winget update), artificial stress tensor
// (Eq. 19-20), deformation gradient with an intermediate reference configuration (Eq. 28-30), error
// vector (Eq. 31) and the stiffness, viscous and combined hourglass forces (Eq. 32-34). The
// momentum and continuity equations with Sigma = -p I + S are the shared SphEquations (core).
#include <memory>
#include <vector>

#include "core/simulation.hpp"
#include "solid/nonlocal_damage.hpp"
#include "solid/solid_keys.hpp"
#include "solid/solid_material.hpp"
#include "total_lagrangian.hpp"

namespace monosph {

// Minimum image of a difference d of initial positions; period_a is the domain's length along a
// periodic axis a and 0 along the others. |d_a| < period_a, so rint (one instruction) never meets
// the tie where it would differ from round.
template <int D>
inline Vec<D> minimum_image(Vec<D> d, const Vec<D>& period) {
  for (int a = 0; a < D; ++a)
    if (period[a] > 0) d[a] -= period[a] * std::rint(d[a] / period[a]);
  return d;
}

template <int D>
class SolidModule : public Module<D> {
 public:
  explicit SolidModule(Simulation<D>& sim);
  std::string name() const override { return "solid"; }
  bool fast() const override { return true; }  // solids only
  void on_create(Simulation<D>& sim) override;
  void drift(Simulation<D>& sim, double dt) override;
  void constitutive(Simulation<D>& sim) override;
  void rates(Simulation<D>& sim) override;
  void sums(Simulation<D>& sim) override;
  // Deformation gradients (hourglass control, total Lagrangian F) follow the particles in the
  // acoustic steps of dual-criteria stepping: a stale F against current x_ij would read the
  // whole motion since the last configuration update as hourglass error.
  void acoustic_step(Simulation<D>& sim) override { sums(sim); }
  void forces(Simulation<D>& sim) override;
  void before_rebuild(Simulation<D>& sim) override;
  void on_rebuild(Simulation<D>& sim) override;
  void restarted(Simulation<D>& sim) override {
    if (tl_) tl_->restarted(sim);
  }
  double max_dt(Simulation<D>& sim) override;
  bool reads_pair_rows(int body) const override { return rows_[body] != 0; }

  void diagnostics(Simulation<D>& sim) override;

  // Deformation gradient F = F_ref F_init at the current positions (MMB Eq. 28-30).
  void compute_deformation_gradient(Simulation<D>& sim);
  // Least-squares affine map of the initial onto the current neighbourhood (kernel weights) and
  // the non-affine residual (D^2_min of Falk & Langer 1998) as the disorder measure, in dp.
  void fit_deformation(Simulation<D>& sim, bool store_fit);
  // The total-Lagrangian bodies (Ganzenmueller 2015), null if the scene has none.
  TotalLagrangian<D>* total_lagrangian() { return tl_.get(); }
  Vec<D> initial_difference(const Vec<D>& a, const Vec<D>& b) const {
    return minimum_image<D>(a - b, period_);
  }

 private:
  std::vector<SolidBodyKeys> keys_;  // per body (solid_keys.hpp)
  std::vector<SolidMaterial> mat_;   // per material (solid_material.hpp)
  // Particle i belongs to a solid body of the Eulerian (MMB) formulation.
  bool eulerian(std::int64_t ph, std::int64_t body) const {
    return ph == kSolid && !(tl_ && tl_->is_tl(body));
  }
  std::unique_ptr<TotalLagrangian<D>> tl_;

  // Plasticity, heating and damage (MMB Sect. 2.2-2.3), only when a solid material has them.
  void plastic_return(Simulation<D>& sim, double dt);
  void erode(Simulation<D>& sim);
  // Hertz self-contact between particles of one body (`self_contact`), a floor under r_ij.
  void self_contact(Simulation<D>& sim);
  bool any_self_contact_ = false;
  std::vector<double> contact_w2_;  // self-contact stiffness / mass per particle (last forces)
  // Non-hourglass formulation (Zhang et al. 2024): time integral of the Laplacian of v.
  void laplacian_rate(Simulation<D>& sim);  // dI/dt into lap_rate_ (rates: before the drift)
  int klap_ = -1;
  int kep_ = -1, kepr_ = -1, kT_ = -1, kdmg_ = -1, ksy_ = -1, kwp_ = -1;
  bool any_plastic_ = false, any_damage_ = false, any_erosion_ = false;
  int kfail_ = -1;  // elastic energy each particle released when it failed (total_energy)
  // Non-local damage (nonlocal_damage.hpp): per particle its length l, the local increment of
  // the step and the average that grows D.
  void nonlocal_damage(Simulation<D>& sim);
  bool any_nonlocal_ = false;
  NonlocalAverage<D> nonlocal_;
  std::vector<double> dmg_len_, dmg_inc_, dmg_avg_;
  std::vector<char> erode_flag_;  // particles to erode this step (kept: no allocation per step)

  int kS_, kvm_, kX0_, kXref_, kF_, kFref_, kFinit_, kdis_, kgradv_, kas_ = -1, kFls_ = -1,
                                                                     khge_ = -1;
  bool any_ls_ = false;
  bool any_as_ = false;
  // Reference pair list (rebuilt at every neighbour rebuild): j, image shift code (into the
  // neighbour list's table), and g_ij = V_j L_ref,i grad W(X_ij) in the reference configuration.
  std::vector<std::size_t> rstart_;
  std::vector<int> rj_;
  std::vector<std::uint8_t> rcode_;
  std::vector<Vec<D>> rg_;
  std::vector<Vec<D>> lap_rate_;  // Zhang et al. 2024, Eq. 19: dI_i/dt of the step
  std::vector<double> omega2_;    // hourglass spring frequency bound per particle (last forces)
  std::vector<char> rows_;        // per body: its pair rows are read (reads_pair_rows)
  Vec<D> period_;  // domain length along periodic axes, 0 along the others (minimum_image)
};

}  // namespace monosph
