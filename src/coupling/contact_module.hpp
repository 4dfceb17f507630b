#pragma once
// Contact of rigid-cluster particles with the particles of other bodies: grain - solid, grain -
// wall and grain - grain (Mohseni-Mofidi & Bierwisch 2020 Sect. 3.6: "inter-particle repulsive
// forces according to Cleary et al. 2012"). Cleary's law is not available to us; the substitute
// (../shared/reference/equations.md Sect. 6) is a central pair force between spheres of diameter
// d_c = distance * dp:
//  - hertz (default): F = 4/3 E* sqrt(R*) delta^1.5 with delta = d_c - r, R* = d_c/4 and
//    1/E* = (1 - nu_i^2)/E_i + (1 - nu_j^2)/E_j from the two materials (Johnson 1985, Eq. 4.23),
//    optionally with a normal dashpot (ratio of critical);
//  - lennard_jones: F = m_ij D [(d_c/r)^p1 - (d_c/r)^p2] / r (Monaghan 1994, JCP 110:399) with
//    the pair mass m_ij = 2 m_i m_j/(m_i + m_j), so that the pair force is antisymmetric;
//  - either law: Coulomb friction mu F_n against the pair's sliding (`friction`, default 0).
// 2D forces are per metre of depth: the 3D point force is divided by t_z = dp (equations.md Sect.
// 0). Each particle sums its own side of every pair: exactly opposite forces, momentum conserved to
// round-off. Contact pairs take no part in any SPH sum. Probes: grain_impacts (clusters that came
// into contact with a solid or wall body, counted at first touch; released beyond 1.1 d_c),
// contact_pairs (pairs in contact now) and, through potential_energy, contact_energy.
#include <vector>

#include "core/simulation.hpp"
#include "coupling/coupling_keys.hpp"

namespace monosph {

template <int D>
class ContactModule : public Module<D> {
 public:
  explicit ContactModule(Simulation<D>& sim);
  std::string name() const override { return "contact"; }
  void forces(Simulation<D>& sim) override;
  void on_rebuild(Simulation<D>& sim) override;
  double max_dt(Simulation<D>& sim) override;
  std::vector<std::string> probe_columns(const ProbeSpec& s) const override;
  void probe(Simulation<D>& sim, const ProbeSpec& s, std::vector<double>& out) override;
  void save_state(std::map<std::string, double>& s) const override;
  void load_state(Simulation<D>& sim, const std::map<std::string, double>& s) override;

  // Magnitude of the repulsive force of a pair at distance r (before any damping), per depth.
  double pair_force(double r, int material_i, int material_j, double m_i, double m_j) const;
  // Elastic energy of a pair at distance r, the integral of pair_force from r to d_c (zero at
  // and beyond d_c; dU/dr = -F), per depth in 2D.
  double pair_energy(double r, int material_i, int material_j, double m_i, double m_j) const;
  // This rank's share of the energy of all contact pairs now: half of each pair's energy for
  // each owned particle of it (dashpot work is dissipated, not stored).
  double potential_energy(Simulation<D>& sim) override;
  double contact_modulus(int material_i, int material_j) const {
    return estar_[idx(material_i, material_j)];
  }
  long impacts() const { return impacts_; }
  long pairs() const { return pairs_; }
  double max_overlap() const { return max_overlap_; }  // largest d_c - r in the last pass

 private:
  std::size_t idx(int a, int b) const { return static_cast<std::size_t>(a) * nmat_ + b; }
  ContactSpec spec_;
  bool hertz_ = true;  // spec_.law == "hertz"
  double dc_ = 0, depth_ = 1;
  std::size_t nmat_ = 0;
  std::vector<double> estar_;  // per material pair
  int kcl_, kcf_;
  std::vector<char> touch_, near_;  // per particle: touching / within 1.1 d_c of a solid or wall
  std::vector<char> in_contact_;    // per cluster
  std::vector<char> touching_, close_;  // per cluster, this pass
  std::vector<double> reduce_buf_;      // both, for the MPI reduction
  std::vector<std::size_t> rigid_;      // indices of the rigid particles (since the last rebuild)
  long impacts_ = 0, pairs_ = 0;
  double max_overlap_ = 0, omega2_ = 0;
};

}  // namespace monosph
