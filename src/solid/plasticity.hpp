#pragma once
// J2 plasticity with Johnson-Cook hardening, adiabatic heating and Johnson-Cook damage
// (Mohseni-Mofidi & Bierwisch 2020, "MMB", Sect. 2.2-2.3, Eq. 22-26).
#include "core/types.hpp"
#include "scene/scene.hpp"
#include "solid/solid_material.hpp"

namespace monosph {

// Homologous temperature T* = (T - T_ref)/(T_melt - T_ref), clamped to [0, 1]; 0 without T_melt.
double homologous_temperature(const JohnsonCook& jc, double T);

// Yield stress of MMB Eq. 23. The rate factor is clamped at 1 for rates below rate0 (the log
// would soften the material below its quasi-static curve), the thermal factor at T* in [0, 1].
double jc_yield(const JohnsonCook& jc, double eps_p, double rate, double T);

struct ReturnResult {
  double deps = 0;     // plastic strain increment
  double sigma_y = 0;  // yield stress at the returned state
  bool plastic = false;
};

// Elastic predictor / plastic corrector (MMB Eq. 22) by radial return: the trial deviator S is
// scaled back onto sigma_eq = sigma_y(eps_p + deps, deps/dt, T). For J2 this is the closest-point
// projection (Simo & Hughes 1998, Box 3.1); the scalar consistency equation
//   sigma_tr - 3 mu deps = sigma_y(eps_p + deps, deps/dt, T)
// is solved by safeguarded Newton to 1e-12 relative, so the result lies on the yield surface
// whatever the step (the cutting plane of MMB converges to the same point).
ReturnResult radial_return(Mat3& S, double mu, const JohnsonCook& jc, double eps_p, double T,
                           double dt);

// Johnson-Cook failure strain (MMB Eq. 26) at triaxiality sigma* = -p/sigma_eq; the rate factor
// uses max(rate/rate0, 1); floored at d.min_failure_strain (default 1e-6: very high
// triaxiality fails at once).
double jc_failure_strain(const JohnsonCookDamage& d, const JohnsonCook& jc, double triaxiality,
                         double rate, double T);

// State of one material point carried between steps.
struct PlasticPoint {
  double eps_p = 0;     // equivalent plastic strain
  double rate = 0;      // its rate over the last step
  double T = 293.15;    // temperature (K)
  double D = 0;         // Johnson-Cook damage, failed at 1
  double sigma_y = 0;   // yield stress at the last return
  double dD = 0;        // this step's local damage increment (MMB Eq. 25)
  double released = 0;  // elastic energy per unit volume released when the point failed this step
};

// One step after the elastic predictor S (trial deviator): return mapping (Eq. 22-23), adiabatic
// heating (Eq. 24), damage growth (Eq. 25-26) with the pressure p = K (rho/rho0 - 1) (Eq. 13).
// A failed point (D >= 1) keeps S = 0 for good. Returns true if the step was plastic.
// With `defer_damage` (non-local damage) D is left alone: the caller adds an average of dD.
bool plastic_update(Mat3& S, PlasticPoint& pt, const Material& m, const SolidMaterial& sm,
                    double rho, double dt, bool defer_damage = false);

// Adds dD to the damage of a point; at D = 1 the point fails: S = 0, and `released` holds the
// elastic energy per unit volume it had (S:S/(4 mu) + a tensile p^2/(2 K)).
void add_damage(Mat3& S, PlasticPoint& pt, const Material& m, double rho, double dD);

}  // namespace monosph
