#pragma once
// Rigid surfaces with prescribed motion and their contact with SPH particles (Mohseni-Mofidi &
// Bierwisch 2020, Sect. 3, first paragraph): "a repulsive Hertzian normal force and a Coulomb
// friction tangential force between a sphere with a diameter equal to the particle spacing and the
// spatially closest triangle of the surface". Scene section `surfaces`; probes `surface_force`
// (total force of the particles on a surface) and `surface_contacts` (particles touching it).
#include <string>
#include <vector>

#include "core/simulation.hpp"
#include "scene/expression.hpp"
#include "surface.hpp"

namespace monosph {

template <int D>
class RigidSurfaceModule : public Module<D> {
 public:
  // Builds every surface of the scene (reads STL files; InputError naming the key or file).
  explicit RigidSurfaceModule(Simulation<D>& sim);
  std::string name() const override { return "rigid"; }
  void on_create(Simulation<D>& sim) override;  // initial temperatures (surface heat only)
  void drift(Simulation<D>& sim, double dt) override;
  void forces(Simulation<D>& sim) override;
  double max_dt(Simulation<D>& sim) override;
  bool reads_pair_rows(int) const override { return false; }  // no pair passes
  std::vector<std::string> probe_columns(const ProbeSpec& spec) const override;
  void probe(Simulation<D>& sim, const ProbeSpec& spec, std::vector<double>& out) override;
  // This rank's share of the Hertz energy 8/15 E* sqrt(R) delta^2.5 (per depth in 2D) of the
  // owned particles touching a surface now; friction and the dashpot store none.
  double potential_energy(Simulation<D>& sim) override;

  std::size_t size() const { return s_.size(); }
  int find(const std::string& name) const;  // -1 if there is no such surface
  const std::string& surface_name(int s) const { return s_[s].name; }
  // Elements in the surface's frame at t = 0; the surface now is that plus displacement(s).
  const SurfaceGeometry<D>& geometry(int s) const { return s_[s].geometry; }
  const Vec<D>& displacement(int s) const { return s_[s].displacement; }
  const Vec<D>& velocity(int s) const { return s_[s].velocity; }  // at the last force pass
  // Force of the particles on the surface (minus the sum of the contact forces on them) and the
  // number of particles touching it, from the last force pass. Per metre of depth in 2D.
  const Vec<D>& reaction(int s) const { return s_[s].reaction; }
  int contacts(int s) const { return s_[s].contacts; }
  // Contact force of surface s on each particle (last force pass, particle order of that pass).
  const std::vector<Vec<D>>& particle_forces(int s) const { return s_[s].force; }
  // Contact modulus E* of surface s with a material (index into the scene's materials).
  double contact_modulus(int s, int material) const { return s_[s].e_star[material]; }

 private:
  struct Surface {
    std::string name;
    SurfaceGeometry<D> geometry;
    std::vector<Expression> velocity_expr;
    bool constant = true;
    Vec<D> v0 = Vec<D>::Zero();  // the velocity when constant
    double friction = 0;
    double friction_cap = 0;     // tau_max dp^(D-1): the largest friction force per particle
    double heat_partition = 1;   // beta: the surface's share of the friction work
    double conductance = 0;      // h_c dp^(D-1): W/K per touching particle (0: no heat sink)
    double temperature = 0;      // the surface's fixed temperature
    double damping = 0;          // normal dashpot, ratio of critical
    std::vector<double> e_star;  // per material
    Vec<D> displacement = Vec<D>::Zero(), velocity = Vec<D>::Zero(), reaction = Vec<D>::Zero();
    int contacts = 0;
    std::vector<Vec<D>> force;  // per particle
  };
  Vec<D> velocity_at(const Surface& s, double t) const;
  void sync(double t);  // displacements at time t from t = 0 (a restart)

  std::vector<Surface> s_;
  double t_ = 0;       // time of the displacements
  double omega2_ = 0;  // largest contact frequency squared k/m (last force pass)
  double radius_ = 0;  // dp/2
  double depth_ = 1;   // 1 in 3D, dp in 2D
  // Friction heat and heat transfer to the surfaces (some surface has heat_partition < 1 or
  // heat_transfer > 0): the fields `temperature` and `surface_heating` (dT/dt, K/s, from the last
  // force pass; applied in drift as the heat module's conduction rate is). -1: none.
  int kT_ = -1, kq_ = -1;
};

}  // namespace monosph
