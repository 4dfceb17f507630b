#pragma once
// Pieces of the particle contact laws shared by the grain contact (contact_module) and the contact
// between solid bodies (solid_contact_module): the plane-strain compliance of a material (for the
// Hertz E*) and the regularised Coulomb friction of a pair.
#include "core/types.hpp"
#include "scene/scene.hpp"

namespace monosph {

// Plane-strain compliance (1 - nu^2)/E of a material (Johnson 1985, Eq. 4.23: 1/E* is the sum of
// the two bodies' compliances); a material without shear modulus (a fluid used for wall particles)
// takes its bulk modulus as the plane-strain modulus.
inline double compliance(const Material& m) {
  const double k = m.bulk_modulus, mu = m.shear_modulus;
  if (!(mu > 0)) return 1.0 / k;
  const double e = 9 * k * mu / (3 * k + mu), nu = (3 * k - 2 * mu) / (2 * (3 * k + mu));
  return (1 - nu * nu) / e;
}

// Coulomb friction on particle i of a pair in contact: -min(mu F_n, m* |v_t|/dt) v_t/|v_t| with
// the relative tangential velocity v_t of i against j (Cundall & Strack 1979, regularised as the
// rigid surfaces, src/rigid/surface.cpp: it never more than stops the sliding of the pair in one
// step). j gets the opposite force: momentum is exact; the pair's torque goes into the bodies'
// rotation (particles carry no spin).
template <int D>
Vec<D> friction(const Vec<D>& v_ij, const Vec<D>& n, double f_n, double mu, double m_star,
                double dt) {
  const Vec<D> vt = v_ij - v_ij.dot(n) * n;
  const double s = vt.norm();
  if (!(s > 0) || !(f_n > 0)) return Vec<D>::Zero();
  double f_t = mu * f_n;
  if (dt > 0) f_t = std::min(f_t, m_star * s / dt);
  return (-f_t / s) * vt;
}

}  // namespace monosph
