// Self-contact of a solid body (key `self_contact`): Hertz springs between particles of one
// body that come closer than d_c, part of SolidModule::forces.
#include "core/hertz.hpp"
#include "solid_module.hpp"

namespace monosph {

template <int D>
void SolidModule<D>::self_contact(Simulation<D>& sim) {
  // Hertz contact of two spheres of diameter d_c = self_contact dp (Johnson 1985, Eq. 4.23):
  // F = 4/3 E* sqrt(R*) delta^1.5, delta = d_c - r, R* = d_c/4, 1/E* = 2 (1 - nu^2)/E; per depth
  // dp in 2D. Each particle sums its own side of every pair: exactly opposite forces.
  auto& p = sim.particles();
  const auto& pl = sim.pairs();
  auto x = p.x();
  auto a = p.a();
  auto m = p.m();
  auto ph = p.phase();
  auto bd = p.body();
  auto mt = p.material();
  const auto& mats = sim.materials();
  const double dp = sim.dp(), depth = D == 2 ? dp : 1.0;
  const std::size_t n = p.size();
  contact_w2_.assign(n, 0.0);
#pragma omp parallel for schedule(runtime)
  for (std::size_t i = 0; i < n; ++i) {
    if (ph[i] != kSolid) continue;
    const double dc = keys_[bd[i]].self_contact * dp;
    if (!(dc > 0)) continue;
    const Material& mat = mats[mt[i]];
    const double K = mat.bulk_modulus, mu = mat.shear_modulus;
    const double nu = (3 * K - 2 * mu) / (2 * (3 * K + mu));
    const double estar = mat.youngs_modulus() / (2 * (1 - nu * nu)), rstar = 0.25 * dc;
    Vec<D> f = Vec<D>::Zero();
    double kn = 0;
    for (std::size_t k = pl.begin(i); k < pl.end(i); ++k) {
      const int j = pl.j[k];
      if (bd[j] != bd[i]) continue;
      const Vec<D> rij = pl.r(x, i, k);
      const double r = rij.norm();
      if (r >= dc || r == 0) continue;
      const double delta = dc - r;
      f += (hertz_force(estar, rstar, delta) / depth / r) * rij;
      // dF/d(delta), at an overlap of at least 0.1 R (as the grain contact)
      kn += hertz_stiffness(estar, rstar, std::max(delta, 0.05 * dc)) / depth;
    }
    a[i] += f / m[i];
    contact_w2_[i] = kn / m[i];
  }
}

template void SolidModule<2>::self_contact(Simulation<2>&);
template void SolidModule<3>::self_contact(Simulation<3>&);

}  // namespace monosph
