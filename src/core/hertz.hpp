#pragma once
// Hertz contact of a sphere of radius R with a flat, or of two spheres with R = R1 R2/(R1 + R2)
// (Johnson 1985, Contact Mechanics, Eq. 4.23): F = 4/3 E* sqrt(R) delta^(3/2), and its stiffness
// dF/d(delta) = 2 E* sqrt(R delta), and its energy. Used by rigid surfaces, grain contact and solid
// self-contact.
#include <cmath>

namespace monosph {

inline double hertz_force(double e_star, double radius, double overlap) {
  return overlap > 0 ? 4.0 / 3.0 * e_star * std::sqrt(radius) * overlap * std::sqrt(overlap) : 0.0;
}
inline double hertz_stiffness(double e_star, double radius, double overlap) {
  return overlap > 0 ? 2.0 * e_star * std::sqrt(radius * overlap) : 0.0;
}
// Elastic energy stored in the contact, the integral of the force over the overlap:
// U = 8/15 E* sqrt(R) delta^(5/2) (dU/d(delta) = F).
inline double hertz_energy(double e_star, double radius, double overlap) {
  return overlap > 0
             ? 8.0 / 15.0 * e_star * std::sqrt(radius) * overlap * overlap * std::sqrt(overlap)
             : 0.0;
}

}  // namespace monosph
