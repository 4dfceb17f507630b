#pragma once
// Sub-grid lubrication between a rigid cluster and a nearby surface (solid, wall or another
// cluster) once the fluid film between them is thinner than the particles resolve
// (docs/theory.md, "Lubrication below the resolved gap"). Normal squeeze force on approach, in
// the shifted form of resolved-particle codes (Ball & Melrose 1995; Bian & Ellero 2014), so that
// it adds only what the SPH fluid misses below the resolved gap h_c:
//   2D, per depth: F = 3 sqrt(2) pi mu U a^1.5 (H^-1.5 - h_c^-1.5)  (cylinder-plane, Jeffrey &
//                  Onishi 1981, leading order)
//   3D:            F = 6 pi mu U a^2 (1/H - 1/h_c)                   (sphere-plane, Brenner 1961)
// with H = max(h, h_min), h the surface gap (closest pair distance minus dp), U the approach
// speed, a the cluster's radius (two clusters: a1 a2/(a1 + a2)). None on separation: the film
// cavitates (its tension would be limited to the ambient pressure). The force is shared among
// the pairs of the film (weight 1/H_ij^2, the Reynolds pressure), as central pair forces: linear
// and angular momentum are conserved; each pair's share is capped by what stops that pair's
// approach in one step (an implicit damper), so the force sets no time-step limit.
#include <vector>

#include "core/simulation.hpp"
#include "coupling/coupling_keys.hpp"

namespace monosph {

template <int D>
class LubricationModule : public Module<D> {
 public:
  explicit LubricationModule(Simulation<D>& sim);
  std::string name() const override { return "lubrication"; }
  void forces(Simulation<D>& sim) override;
  void on_rebuild(Simulation<D>& sim) override;
  std::vector<std::string> probe_columns(const ProbeSpec& s) const override;
  void probe(Simulation<D>& sim, const ProbeSpec& s, std::vector<double>& out) override;

  // Magnitude of the lubrication force at gap h and approach speed U for radius a (per depth in
  // 2D); zero for h >= h_c or U <= 0.
  double force(double h, double U, double a) const;

 private:
  struct Film {  // one cluster's closest surface, this step
    double gap = 0, speed = 0, radius = 0, weight = 0, force = 0;
    long partner = -1;  // body index, or bodies + cluster index for another cluster
  };
  void radii(Simulation<D>& sim);
  long object(std::int64_t body, std::int64_t cluster) const {
    return cluster >= 0 ? nbodies_ + cluster : body;
  }
  void find_films(Simulation<D>& sim);
  double share(const Film& f, double h, double vn, double mstar, double dt) const;
  double mu_ = 0, hc_ = 0, hmin_ = 0;
  int kcl_ = -1;
  long nbodies_ = 0;
  std::vector<double> radius_, mass_;  // per cluster
  std::vector<std::size_t> rigid_;     // indices of the rigid particles
  std::vector<Film> film_;
  std::vector<Film> closest_;  // per rigid particle (rigid_), this step
  std::vector<double> buf_;
  std::vector<Vec<D>> flub_;       // lubrication force on each owned particle, this step
  Vec<D> total_ = Vec<D>::Zero();  // lubrication force on all clusters, this step
};

}  // namespace monosph
