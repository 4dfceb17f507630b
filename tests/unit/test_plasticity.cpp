// J2 plasticity with Johnson-Cook hardening, heating and damage (MMB Eq. 22-26).
#include <gtest/gtest.h>

#include <cmath>

#include "scene/scene.hpp"
#include "solid/elasticity.hpp"
#include "solid/plasticity.hpp"

using namespace monosph;

namespace {
// A shipped material: its generic keys and the solid module's (plasticity, damage).
struct Shipped {
  Material m;
  SolidMaterial sm;
};
Shipped shipped(const std::string& name) {
  return {*library_material(name), *solid_preset(name)};
}
Shipped aluminium() {
  return shipped("Al6061-T6");
}

// Isochoric uniaxial-type deviatoric rate: L = rate diag(1, -1/2, -1/2) (p stays 0).
Mat3 uniaxial(double rate) {
  Mat3 L = Mat3::Zero();
  L(0, 0) = rate, L(1, 1) = L(2, 2) = -0.5 * rate;
  return L;
}
}  // namespace

TEST(Plasticity, LibraryHoldsTable1) {
  const auto [al, al_solid] = aluminium();
  EXPECT_EQ(al.density, 2800);
  EXPECT_EQ(al_solid.plasticity.A, 164e6);
  EXPECT_EQ(al_solid.plasticity.n, 0.465);
  EXPECT_EQ(al_solid.damage.d5, 1.6);
  const auto [pm, pm_solid] = shipped("PMMA");
  EXPECT_EQ(pm.heat_capacity, 1470);
  EXPECT_EQ(pm_solid.plasticity.B, 580e6);
  EXPECT_EQ(pm_solid.damage.d4, -0.0491);
  EXPECT_FALSE(library_material("steel"));
  EXPECT_FALSE(solid_preset("iron"));  // elastic grains: no plasticity
}

TEST(Plasticity, UniaxialFlowCurveFollowsStrainHardening) {
  // Rate and thermal terms off: sigma_eq(eps_p) = A + B eps_p^n; every return on the surface.
  auto [m, sm] = aluminium();
  sm.plasticity.C = 0;
  sm.plasticity.T_melt = 0;
  m.heat_capacity = 0;
  sm.damage.on = false;
  const double rate = 1e3, dt = 2e-8;
  Mat3 S = Mat3::Zero();
  PlasticPoint pt;
  pt.T = 292;
  double worst_curve = 0, worst_surface = 0;
  int plastic_steps = 0;
  for (int k = 0; k < 15000; ++k) {  // total strain 0.3
    S = update_deviatoric(S, uniaxial(rate), m.shear_modulus, dt);
    if (!plastic_update(S, pt, m, sm, m.density, dt)) continue;
    ++plastic_steps;
    const double seq = von_mises(S);
    worst_surface = std::max(worst_surface, std::abs(seq - pt.sigma_y) / pt.sigma_y);
    const double curve = sm.plasticity.A + sm.plasticity.B * std::pow(pt.eps_p, sm.plasticity.n);
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
  JohnsonCook jc = aluminium().sm.plasticity;
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
  const auto [m, sm] = shipped("PMMA");
  const double dt = 1e-7, T = 300;
  for (double trial : {1.2, 2.0, 5.0}) {
    Mat3 S = Mat3::Zero();
    S(0, 0) = 1, S(1, 1) = S(2, 2) = -0.5;
    S *= trial * sm.plasticity.A / von_mises(S);
    const double eps0 = 0.05;
    const ReturnResult r = radial_return(S, m.shear_modulus, sm.plasticity, eps0, T, dt);
    ASSERT_TRUE(r.plastic);
    const double want = jc_yield(sm.plasticity, eps0 + r.deps, r.deps / dt, T);
    EXPECT_NEAR(von_mises(S), want, 1e-8 * want) << trial;
    EXPECT_NEAR(trial * sm.plasticity.A - 3 * m.shear_modulus * r.deps, want, 1e-8 * want);
  }
}

TEST(Plasticity, AdiabaticHeatingIsThePlasticWork) {
  // Perfect plasticity without softening: T - T0 = eta A eps_p / (rho C_p) (MMB Eq. 24).
  auto [m, sm] = aluminium();
  sm.plasticity.B = 0, sm.plasticity.C = 0, sm.plasticity.T_melt = 0;
  sm.damage.on = false;
  Mat3 S = Mat3::Zero();
  PlasticPoint pt;
  pt.T = 300;
  const double rho = 2810, dt = 1e-8;
  for (int k = 0; k < 5000; ++k) {
    S = update_deviatoric(S, uniaxial(1e3), m.shear_modulus, dt);
    plastic_update(S, pt, m, sm, rho, dt);
  }
  ASSERT_GT(pt.eps_p, 0.04);
  const double want = 0.9 * sm.plasticity.A * pt.eps_p / (rho * m.heat_capacity);
  EXPECT_NEAR(pt.T - 300, want, 1e-9 * want);
}

TEST(Plasticity, DamageGrowsAsEq25And26AtConstantTriaxiality) {
  // Perfect plasticity keeps sigma_eq = A, and a fixed density keeps p: constant triaxiality,
  // so D = eps_p / eps_f exactly until failure; afterwards S stays zero under further loading.
  auto [m, sm] = aluminium();
  sm.plasticity.B = 0, sm.plasticity.C = 0, sm.plasticity.T_melt = 0;
  m.heat_capacity = 0;
  const double rho = m.density * (1 - 1e-3);  // tension: p = -K 1e-3 = -69 MPa
  const double p = m.bulk_modulus * (rho / m.density - 1);
  const double triax = -p / sm.plasticity.A;
  const double ef = (sm.damage.d1 + sm.damage.d2 * std::exp(sm.damage.d3 * triax)) *
                    (1 + sm.damage.d5 * 0.0);  // D4 = 0 for Al; no thermal term
  EXPECT_NEAR(jc_failure_strain(sm.damage, sm.plasticity, triax, 1e3, 292), ef, 1e-14);
  Mat3 S = Mat3::Zero();
  PlasticPoint pt;
  pt.T = 292;
  const double dt = 1e-7;
  double worst = 0;
  bool failed = false;
  for (int k = 0; k < 40000 && !failed; ++k) {
    S = update_deviatoric(S, uniaxial(1e3), m.shear_modulus, dt);
    plastic_update(S, pt, m, sm, rho, dt);
    if (pt.D < 1) worst = std::max(worst, std::abs(pt.D - pt.eps_p / ef));
    failed = pt.D >= 1;
  }
  ASSERT_TRUE(failed);
  EXPECT_LT(worst, 1e-12);
  EXPECT_NEAR(pt.eps_p, ef, 1e-3 * ef);  // fails within one step of eps_p = eps_f
  EXPECT_EQ(von_mises(S), 0.0);
  for (int k = 0; k < 100; ++k) {
    S = update_deviatoric(S, uniaxial(1e3), m.shear_modulus, dt);
    plastic_update(S, pt, m, sm, rho, dt);
    EXPECT_EQ(von_mises(S), 0.0);
  }
}

TEST(Plasticity, ElasticStepsLeaveTheStressAlone) {
  auto [m, sm] = aluminium();
  Mat3 S = Mat3::Zero();
  S(0, 1) = S(1, 0) = 0.5 * sm.plasticity.A / std::sqrt(3.0);
  const Mat3 before = S;
  PlasticPoint pt;
  pt.T = 292;
  EXPECT_FALSE(plastic_update(S, pt, m, sm, m.density, 1e-8));
  EXPECT_EQ((S - before).norm(), 0.0);
  EXPECT_EQ(pt.eps_p, 0.0);
  EXPECT_EQ(pt.D, 0.0);
}
