// J2 plasticity with Johnson-Cook hardening, heating and damage (MMB Eq. 22-26).
#include <gtest/gtest.h>

#include <cmath>

#include "scene/scene.hpp"
#include "solid/elasticity.hpp"
#include "solid/plasticity.hpp"

using namespace monosph;

namespace {
Material aluminium() {
  Material m = *library_material("Al6061-T6");
  return m;
}

// Isochoric uniaxial-type deviatoric rate: L = rate diag(1, -1/2, -1/2) (p stays 0).
Mat3 uniaxial(double rate) {
  Mat3 L = Mat3::Zero();
  L(0, 0) = rate, L(1, 1) = L(2, 2) = -0.5 * rate;
  return L;
}
}  // namespace

TEST(Plasticity, LibraryHoldsTable1) {
  const Material al = aluminium();
  EXPECT_EQ(al.plasticity.A, 164e6);
  EXPECT_EQ(al.plasticity.n, 0.465);
  EXPECT_EQ(al.damage.d5, 1.6);
  const Material pm = *library_material("PMMA");
  EXPECT_EQ(pm.plasticity.B, 580e6);
  EXPECT_EQ(pm.damage.d4, -0.0491);
  EXPECT_FALSE(library_material("steel"));
}

TEST(Plasticity, UniaxialFlowCurveFollowsStrainHardening) {
  // Rate and thermal terms off: sigma_eq(eps_p) = A + B eps_p^n; every return on the surface.
  Material m = aluminium();
  m.plasticity.C = 0;
  m.plasticity.T_melt = 0;
  m.heat_capacity = 0;
  m.damage.on = false;
  const double rate = 1e3, dt = 2e-8;
  Mat3 S = Mat3::Zero();
  PlasticPoint pt;
  pt.T = 292;
  double worst_curve = 0, worst_surface = 0;
  int plastic_steps = 0;
  for (int k = 0; k < 15000; ++k) {  // total strain 0.3
    S = update_deviatoric(S, uniaxial(rate), m.shear_modulus, dt);
    if (!plastic_update(S, pt, m, m.density, dt)) continue;
    ++plastic_steps;
    const double seq = von_mises(S);
    worst_surface = std::max(worst_surface, std::abs(seq - pt.sigma_y) / pt.sigma_y);
    const double curve = m.plasticity.A + m.plasticity.B * std::pow(pt.eps_p, m.plasticity.n);
    worst_curve = std::max(worst_curve, std::abs(seq - curve) / curve);
  }
  EXPECT_GT(plastic_steps, 10000);
  EXPECT_GT(pt.eps_p, 0.28);
  EXPECT_LT(worst_surface, 1e-8);
  EXPECT_LT(worst_curve, 5e-3);
  // The plastic strain is the total equivalent strain minus the elastic part sigma_eq / (3 mu).
  EXPECT_NEAR(pt.eps_p, 0.3 - von_mises(S) / (3 * m.shear_modulus), 1e-9);
}

TEST(Plasticity, RateAndThermalFactorsAreThoseOfEq23) {
  JohnsonCook jc = aluminium().plasticity;
  const double eps = 0.1, T = jc.T_ref + 0.4 * (jc.T_melt - jc.T_ref);
  const double base = jc.A + jc.B * std::pow(eps, jc.n);
  EXPECT_DOUBLE_EQ(jc_yield(jc, eps, 0.5 * jc.rate0, jc.T_ref), base);  // rate factor >= 1
  EXPECT_NEAR(jc_yield(jc, eps, 1e4 * jc.rate0, jc.T_ref), base * (1 + jc.C * std::log(1e4)),
              1e-9 * base);
  EXPECT_NEAR(jc_yield(jc, eps, 0, T), base * (1 - std::pow(0.4, jc.m)), 1e-9 * base);
  EXPECT_EQ(jc_yield(jc, eps, 0, jc.T_melt + 10), 0.0);
  EXPECT_DOUBLE_EQ(jc_yield(jc, eps, 0, jc.T_ref - 50), base);  // no hardening below T_ref
}

TEST(Plasticity, ReturnWithRateHardeningLandsOnTheRateDependentSurface) {
  // A fast step: the return must satisfy sigma_eq = sigma_y(eps + d, d/dt, T) with the rate of
  // the increment itself (PMMA: C = 0.081 and rate0 = 1e-3, a strong rate term).
  const Material m = *library_material("PMMA");
  const double dt = 1e-7, T = 300;
  for (double trial : {1.2, 2.0, 5.0}) {
    Mat3 S = Mat3::Zero();
    S(0, 0) = 1, S(1, 1) = S(2, 2) = -0.5;
    S *= trial * m.plasticity.A / von_mises(S);
    const double eps0 = 0.05;
    const ReturnResult r = radial_return(S, m.shear_modulus, m.plasticity, eps0, T, dt);
    ASSERT_TRUE(r.plastic);
    const double want = jc_yield(m.plasticity, eps0 + r.deps, r.deps / dt, T);
    EXPECT_NEAR(von_mises(S), want, 1e-8 * want) << trial;
    EXPECT_NEAR(trial * m.plasticity.A - 3 * m.shear_modulus * r.deps, want, 1e-8 * want);
  }
}

TEST(Plasticity, AdiabaticHeatingIsThePlasticWork) {
  // Perfect plasticity without softening: T - T0 = eta A eps_p / (rho C_p) (MMB Eq. 24).
  Material m = aluminium();
  m.plasticity.B = 0, m.plasticity.C = 0, m.plasticity.T_melt = 0;
  m.damage.on = false;
  Mat3 S = Mat3::Zero();
  PlasticPoint pt;
  pt.T = 300;
  const double rho = 2810, dt = 1e-8;
  for (int k = 0; k < 5000; ++k) {
    S = update_deviatoric(S, uniaxial(1e3), m.shear_modulus, dt);
    plastic_update(S, pt, m, rho, dt);
  }
  ASSERT_GT(pt.eps_p, 0.04);
  const double want = 0.9 * m.plasticity.A * pt.eps_p / (rho * m.heat_capacity);
  EXPECT_NEAR(pt.T - 300, want, 1e-9 * want);
}

TEST(Plasticity, DamageGrowsAsEq25And26AtConstantTriaxiality) {
  // Perfect plasticity keeps sigma_eq = A, and a fixed density keeps p: constant triaxiality,
  // so D = eps_p / eps_f exactly until failure; afterwards S stays zero under further loading.
  Material m = aluminium();
  m.plasticity.B = 0, m.plasticity.C = 0, m.plasticity.T_melt = 0;
  m.heat_capacity = 0;
  const double rho = m.density * (1 - 1e-3);  // tension: p = -K 1e-3 = -69 MPa
  const double p = m.bulk_modulus * (rho / m.density - 1);
  const double triax = -p / m.plasticity.A;
  const double ef = (m.damage.d1 + m.damage.d2 * std::exp(m.damage.d3 * triax)) *
                    (1 + m.damage.d5 * 0.0);  // D4 = 0 for Al; no thermal term
  EXPECT_NEAR(jc_failure_strain(m.damage, m.plasticity, triax, 1e3, 292), ef, 1e-14);
  Mat3 S = Mat3::Zero();
  PlasticPoint pt;
  pt.T = 292;
  const double dt = 1e-7;
  double worst = 0;
  bool failed = false;
  for (int k = 0; k < 40000 && !failed; ++k) {
    S = update_deviatoric(S, uniaxial(1e3), m.shear_modulus, dt);
    plastic_update(S, pt, m, rho, dt);
    if (pt.D < 1) worst = std::max(worst, std::abs(pt.D - pt.eps_p / ef));
    failed = pt.D >= 1;
  }
  ASSERT_TRUE(failed);
  EXPECT_LT(worst, 1e-12);
  EXPECT_NEAR(pt.eps_p, ef, 1e-3 * ef);  // fails within one step of eps_p = eps_f
  EXPECT_EQ(von_mises(S), 0.0);
  for (int k = 0; k < 100; ++k) {
    S = update_deviatoric(S, uniaxial(1e3), m.shear_modulus, dt);
    plastic_update(S, pt, m, rho, dt);
    EXPECT_EQ(von_mises(S), 0.0);
  }
}

TEST(Plasticity, ElasticStepsLeaveTheStressAlone) {
  Material m = aluminium();
  Mat3 S = Mat3::Zero();
  S(0, 1) = S(1, 0) = 0.5 * m.plasticity.A / std::sqrt(3.0);
  const Mat3 before = S;
  PlasticPoint pt;
  pt.T = 292;
  EXPECT_FALSE(plastic_update(S, pt, m, m.density, 1e-8));
  EXPECT_EQ((S - before).norm(), 0.0);
  EXPECT_EQ(pt.eps_p, 0.0);
  EXPECT_EQ(pt.D, 0.0);
}
