#include "plasticity.hpp"

#include <algorithm>
#include <cmath>

#include "elasticity.hpp"

namespace monosph {

double homologous_temperature(const JohnsonCook& jc, double T) {
  if (jc.T_melt <= jc.T_ref) return 0;
  return std::clamp((T - jc.T_ref) / (jc.T_melt - jc.T_ref), 0.0, 1.0);
}

namespace {
// First and third factors of MMB Eq. 23.
double hardening(const JohnsonCook& jc, double e) {
  return jc.A + (jc.B > 0 && e > 0 ? jc.B * std::pow(e, jc.n) : 0.0);
}
double thermal_factor(const JohnsonCook& jc, double T) {
  const double ts = homologous_temperature(jc, T);
  return ts > 0 ? 1 - std::pow(ts, jc.m) : 1.0;
}

// The three factors of MMB Eq. 23 and the derivative of the first two with respect to deps.
struct Yield {
  double value, slope;
};

Yield yield_and_slope(const JohnsonCook& jc, double eps_p, double deps, double dt, double theta) {
  const double e = eps_p + deps;
  const double hard = hardening(jc, e);
  const double dhard = jc.B > 0 && e > 0 ? jc.B * jc.n * std::pow(e, jc.n - 1) : 0.0;
  double rate_f = 1, drate_f = 0;
  if (jc.C > 0 && dt > 0 && deps > 0) {
    const double ratio = deps / (dt * jc.rate0);
    if (ratio > 1) rate_f = 1 + jc.C * std::log(ratio), drate_f = jc.C / deps;
  }
  return {hard * rate_f * theta, (dhard * rate_f + hard * drate_f) * theta};
}
}  // namespace

double jc_yield(const JohnsonCook& jc, double eps_p, double rate, double T) {
  const double rate_f = jc.C > 0 && rate > jc.rate0 ? 1 + jc.C * std::log(rate / jc.rate0) : 1.0;
  return hardening(jc, eps_p) * rate_f * thermal_factor(jc, T);
}

ReturnResult radial_return(Mat3& S, double mu, const JohnsonCook& jc, double eps_p, double T,
                           double dt) {
  ReturnResult r;
  const double theta = thermal_factor(jc, T);
  const double s_tr = von_mises(S);
  // Elastic predictor: the rate factor is 1 at zero plastic rate (MMB Eq. 22-23).
  r.sigma_y = yield_and_slope(jc, eps_p, 0.0, dt, theta).value;
  if (s_tr <= r.sigma_y) return r;
  r.plastic = true;
  if (theta <= 0) {  // molten: no deviatoric stress
    r.deps = s_tr / (3 * mu);
    r.sigma_y = 0;
    S.setZero();
    return r;
  }
  // g(x) = s_tr - 3 mu x - sigma_y(x) decreases monotonically from g(0) > 0 to g(hi) < 0.
  double lo = 0, hi = s_tr / (3 * mu), x = 0;
  for (int it = 0; it < 200; ++it) {
    const Yield y = yield_and_slope(jc, eps_p, x, dt, theta);
    const double g = s_tr - 3 * mu * x - y.value;
    if (std::abs(g) <= 1e-13 * s_tr) break;
    (g > 0 ? lo : hi) = x;
    const double slope = 3 * mu + y.slope;
    double xn = x + g / slope;
    if (!(xn > lo && xn < hi) || !std::isfinite(xn)) xn = 0.5 * (lo + hi);  // safeguard
    if (hi - lo <= 1e-16 * hi) break;
    x = xn;
  }
  r.deps = x;
  r.sigma_y = s_tr - 3 * mu * x;
  S *= r.sigma_y / s_tr;
  return r;
}

double jc_failure_strain(const JohnsonCookDamage& d, const JohnsonCook& jc, double triaxiality,
                         double rate, double T) {
  const double a = d.d1 + d.d2 * std::exp(d.d3 * triaxiality);
  const double b = 1 + d.d4 * std::log(std::max(rate / jc.rate0, 1.0));
  const double c = 1 + d.d5 * homologous_temperature(jc, T);
  return std::max(a * b * c, d.min_failure_strain);
}

void add_damage(Mat3& S, PlasticPoint& pt, const Material& m, double rho, double dD) {
  if (pt.D >= 1 || dD <= 0) return;
  pt.D = std::min(1.0, pt.D + dD);
  if (pt.D < 1) return;
  const double p = m.pressure(rho);
  pt.released = (m.shear_modulus > 0 ? S.cwiseProduct(S).sum() / (4 * m.shear_modulus) : 0.0) +
                (p < 0 ? p * p / (2 * m.bulk_modulus) : 0.0);
  S.setZero();
}

bool plastic_update(Mat3& S, PlasticPoint& pt, const Material& m, const SolidMaterial& sm,
                    double rho, double dt, bool defer_damage) {
  pt.dD = pt.released = 0;
  if (sm.damage.on && pt.D >= 1) {  // failed for good: no deviatoric stress (MMB Sect. 2.3)
    S.setZero();
    pt.rate = 0;
    return false;
  }
  const ReturnResult r = radial_return(S, m.shear_modulus, sm.plasticity, pt.eps_p, pt.T, dt);
  pt.sigma_y = r.sigma_y;
  pt.rate = dt > 0 ? r.deps / dt : 0;
  if (!r.plastic) return false;
  pt.eps_p += r.deps;
  // MMB Eq. 24: Sigma : dEp = sigma_eq deps for J2 flow (the pressure does no plastic work).
  if (m.heat_capacity > 0) pt.T += sm.taylor_quinney * r.sigma_y * r.deps / (rho * m.heat_capacity);
  if (sm.damage.on && r.sigma_y > 0) {
    // MMB Eq. 25-26 with the triaxiality sigma* = -p / sigma_eq.
    const double ef =
        jc_failure_strain(sm.damage, sm.plasticity, -m.pressure(rho) / r.sigma_y, pt.rate, pt.T);
    pt.dD = r.deps / ef;
    if (!defer_damage) add_damage(S, pt, m, rho, pt.dD);
  }
  return true;
}

}  // namespace monosph
