#pragma once
// Contact between solid bodies of different continua (section `solid_contact`). Bodies of one
// continuum share the SPH equations (they are glued: tension and shear cross the interface);
// bodies of different continua take no part in each other's SPH sums and, without this module,
// pass through each other. The module adds a central, repulsive-only pair force between a solid
// particle and every solid particle of another continuum closer than d_c = distance * dp:
// Hertz spheres of diameter d_c, F = 4/3 E* sqrt(R*) delta^1.5, delta = d_c - r, R* = d_c/4,
// 1/E* = (1 - nu_i^2)/E_i + (1 - nu_j^2)/E_j (Johnson 1985, Eq. 4.23), zero for r >= d_c (no
// tension), per depth dp in 2D; optionally a normal dashpot (ratio of critical, Tsuji et al. 1992)
// and Coulomb friction mu F_n against the pair's sliding (Cundall & Strack 1979; contact_law.hpp).
// Each particle sums its own side of every pair: exactly opposite forces, independent of the
// thread count; ghost particles (MPI) carry position, velocity, body and material, which is all a
// pair needs. The step is limited to 20 steps per contact period. Choice of the law and of d_c:
// docs/theory.md, "Contact between solid bodies". Probes: solid_contact_pairs (pairs in contact
// now), solid_contact_force (with `body`: the contact force on it), solid_contact_neighbours
// (pairs of different continua within the kernel support: 0 when the bodies are apart), and the
// stored energy through contact_energy / total_energy.
#include <vector>

#include "core/simulation.hpp"
#include "coupling/coupling_keys.hpp"

namespace monosph {

template <int D>
class SolidContactModule : public Module<D> {
 public:
  explicit SolidContactModule(Simulation<D>& sim);
  std::string name() const override { return "solid_contact"; }
  bool fast() const override { return true; }  // solids only
  void forces(Simulation<D>& sim) override;
  double max_dt(Simulation<D>& sim) override;
  double potential_energy(Simulation<D>& sim) override;
  std::vector<std::string> probe_columns(const ProbeSpec& s) const override;
  void probe(Simulation<D>& sim, const ProbeSpec& s, std::vector<double>& out) override;

  // Repulsive force of a pair at distance r (zero at and beyond d_c), per depth in 2D.
  double pair_force(double r, int material_i, int material_j) const;
  // Elastic energy of a pair at distance r, the integral of pair_force from r to d_c.
  double pair_energy(double r, int material_i, int material_j) const;
  double contact_diameter() const { return dc_; }
  long pairs() const { return pairs_; }
  double max_overlap() const { return max_overlap_; }  // largest d_c - r in the last pass

 private:
  std::size_t idx(int a, int b) const { return static_cast<std::size_t>(a) * nmat_ + b; }
  SolidContactSpec spec_;
  double dc_ = 0, depth_ = 1;
  std::size_t nmat_ = 0;
  std::vector<double> estar_;  // per material pair
  int kcf_;                    // field solid_contact_force (per depth in 2D)
  long pairs_ = 0, near_ = 0;
  double max_overlap_ = 0, omega2_ = 0;
};

}  // namespace monosph
