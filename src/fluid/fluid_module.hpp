#pragma once
// Weakly compressible delta-plus SPH fluid (Sun, Colagrossi, Marrone & Zhang 2017) with the
// generalised wall condition of Adami, Hu & Adams 2012 (equations: shared/reference/
// equations.md, sections 3 and 4; docs/theory.md).
//  - EOS p = c0^2 (rho - rho0) (Sun 2017, Eq. 2; c0 from the material's sound speed), plus the
//    material's background pressure p_b (Morris et al. 1997; flows without a free surface).
//  - Continuity with the delta-SPH diffusive term and the renormalised density gradient
//    (Antuono et al. 2010/2012), momentum with the symmetric pressure pair (p_i + p_j) and the
//    Morris et al. 1997 viscous term (Newtonian nu) plus the delta-SPH alpha term (optional).
//  - delta-plus particle shifting with free-surface detection (lambda, the smallest eigenvalue of
//    the renormalisation matrix; no shift at the surface, tangential shift near it).
//  - Every non-fluid particle (wall layers, and later solid and rigid particles) is a wall-like
//    particle for the fluid: it gets an extrapolated pressure (with the wall acceleration term)
//    and a smoothed fluid velocity (no-slip), and receives the opposite of the force it exerts.
#include <vector>

#include "core/simulation.hpp"
#include "fluid/fluid_keys.hpp"
#include "fluid/fluid_material.hpp"

namespace monosph {

template <int D>
class FluidModule : public Module<D> {
 public:
  explicit FluidModule(Simulation<D>& sim);
  std::string name() const override { return "fluid"; }
  void on_create(Simulation<D>& sim) override;
  void sums(Simulation<D>& sim) override;
  void rates(Simulation<D>& sim) override;
  void drift(Simulation<D>& sim, double dt) override;
  void forces(Simulation<D>& sim) override;
  double max_dt(Simulation<D>& sim) override;
  std::vector<std::string> probe_columns(const ProbeSpec& s) const override;
  void probe(Simulation<D>& sim, const ProbeSpec& s, std::vector<double>& out) override;

 private:
  std::vector<FluidBodyKeys> keys_;                // per body (fluid_keys.hpp)
  void check_no_free_surface(Simulation<D>& sim);  // background pressure: none allowed
  void shift_velocities(Simulation<D>& sim);       // delta-plus or transport-velocity shift
  bool any_shift_ = false, any_consistent_ = false;
  int kpw_, kvw_, kgrad_, klam_, kshift_, kff_, kaw_ = -1, kvprev_ = -1;
  std::vector<double> c0_, rho0_, nu_;  // per material
  std::vector<FluidMaterial> eos_;      // per material (fluid_material.hpp)
  std::vector<Vec<D>> gb_;              // body force per body
  bool any_wall_ = false;
  bool surface_checked_ = false;
  bool central_ = false;  // central viscous form 2 (d + 2) nu pi_ij instead of Morris
};

}  // namespace monosph
