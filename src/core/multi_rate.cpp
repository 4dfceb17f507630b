// Multi-rate stepping (time_step.multi_rate; docs/theory.md, "Multi-rate stepping"): the solids
// take kappa sub-steps of velocity Verlet with their internal (fast) forces inside each step of
// the rest, which is kicked with the slow forces (fluid, grain contact, surfaces, body force).
// The slow forces see the solids' mean velocity and acceleration over the step (Zhang, Rezavand
// & Hu 2021, JCP 429:110028, Sect. 3.3); every slow pair force acts on both partners with the
// same impulse, so total momentum is conserved as in single-rate stepping.
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/simulation.hpp"

namespace monosph {

// First force evaluation of a fresh start (a restart reads the fields from the checkpoint).
template <int D>
void Simulation<D>::init_multi_rate() {
  update_pair_cache(PairRows::read);
  ++configuration_updates_;
  fast_forces(0.0);
  auto v = p_.v();
  auto vb = p_.template view<V>(kvb_);
  std::copy(v.begin(), v.end(), vb.begin());  // the slow passes see v itself
  slow_forces();
  add_fast_acceleration();
  compute_reactions();
  check_guards();
  dt_ = compute_dt_multi_rate();
  dt0_ = dt_;
}

// The sums, constitutive and force passes of the fast (or slow) modules; `reset` sets the
// accelerations they add to.
template <int D>
template <class Reset>
void Simulation<D>::module_forces(bool fast, Reset reset) {
  PassClock clock(pass_seconds_);
  for (auto& m : modules_)
    if (m->fast() == fast) m->sums(*this);
  clock.lap("sums");
  for (auto& m : modules_)
    if (m->fast() == fast) m->constitutive(*this);
  clock.lap("constitutive");
  reset();
  for (auto& m : modules_)
    if (m->fast() == fast) m->forces(*this);
  exchange({p_.find("acceleration")});
  clock.lap("forces");
}

// Fast passes at the current positions: a_fast of the solids (no body force: that is slow).
// The mean of a_fast over the step accumulates with `weight` (1/kappa).
template <int D>
void Simulation<D>::fast_forces(double weight) {
  auto a = p_.a();
  auto af = p_.template view<V>(kaf_);
  auto ab = p_.template view<V>(kab_);
  auto ph = p_.phase();
  const std::size_t n = p_.size();
  module_forces(true, [&] {
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i)
      if (ph[i] == kSolid) a[i].setZero();
  });
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i)
    if (ph[i] == kSolid) af[i] = a[i], ab[i] += weight * a[i];
}

// Slow passes at step n+1 (full pair cache): a_slow of every particle. Solids show their mean
// velocity over the step (x_{n+1} - x_n)/dt and their mean acceleration a_slow,n + <a_fast>.
template <int D>
void Simulation<D>::slow_forces() {
  auto ph = p_.phase();
  const std::size_t n = p_.size();
  auto swap_in = [&] {
    auto v = p_.v();
    auto vb = p_.template view<V>(kvb_);
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i)
      if (ph[i] == kSolid) std::swap(v[i], vb[i]);
  };
  swap_in();
  {
    auto a = p_.a();
    auto as = p_.template view<V>(kas_);
    auto ab = p_.template view<V>(kab_);
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i)
      if (ph[i] == kSolid) a[i] = as[i] + ab[i];  // the wall acceleration of Adami's pressure
  }
  module_forces(false, [&] { body_acceleration(); });
  auto a = p_.a();
  auto as = p_.template view<V>(kas_);
  std::copy(a.begin(), a.end(), as.begin());
  swap_in();  // back: v is the solids' own velocity again
}

// The slow modules' rates over the step, with the solids at their predicted half-step velocity
// v + (dt/2) a_fast (after the slow half kick): single-rate stepping's v_{n+1/2} when kappa = 1.
template <int D>
void Simulation<D>::slow_rates(double dt) {
  auto v = p_.v();
  auto vb = p_.template view<V>(kvb_);
  auto af = p_.template view<V>(kaf_);
  auto ph = p_.phase();
  const std::size_t n = p_.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i)
    if (ph[i] == kSolid) vb[i] = v[i], v[i] += 0.5 * dt * af[i];
  for (auto& m : modules_)
    if (!m->fast()) m->rates(*this);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i)
    if (ph[i] == kSolid) v[i] = vb[i], vb[i].setZero();  // vb now sums the mean velocity
}

// x, rho += dt (v, drho) of the solid particles (`solids`, adding (weight) v to the mean
// velocity) or of all others (then the mean fast acceleration of the solids starts anew).
template <int D>
void Simulation<D>::drift_positions(double dt, bool solids, double weight) {
  auto x = p_.x();
  auto v = p_.v();
  auto rho = p_.rho();
  auto drho = p_.drho();
  auto vb = p_.template view<V>(kvb_);
  auto ab = p_.template view<V>(kab_);
  auto ph = p_.phase();
  const std::size_t n = p_.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const bool solid = ph[i] == kSolid;
    if (solid == solids) x[i] += dt * v[i], rho[i] += dt * drho[i];
    if (solid && solids) vb[i] += weight * v[i];
    if (solid && !solids) ab[i].setZero();
  }
}

// a = a_slow + a_fast on solids (a holds a_slow after the slow passes): output, reactions, dt.
template <int D>
void Simulation<D>::add_fast_acceleration() {
  auto a = p_.a();
  auto af = p_.template view<V>(kaf_);
  auto ph = p_.phase();
  const std::size_t n = p_.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i)
    if (ph[i] == kSolid) a[i] += af[i];
}

// Sub-step of length ds of the solids inside a step dt; the last one also evaluates the slow
// forces (all particles are then at step n+1).
template <int D>
void Simulation<D>::substep(double ds, double dt, bool last) {
  PassClock clock(pass_seconds_);
  auto fast_kick = [&](double t_bc) {
    auto v = p_.v();
    auto af = p_.template view<V>(kaf_);
    auto ph = p_.phase();
    const std::size_t n = p_.size();
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i)
      if (ph[i] == kSolid) v[i] += 0.5 * ds * af[i];
    apply_bc_velocity(t_bc);
  };
  fast_kick(t_ + 0.5 * ds);
  clock.lap("integration");
  for (auto& m : modules_)
    if (m->fast()) m->rates(*this);
  clock.lap("rates");
  drift_positions(ds, true, ds / dt);
  for (auto& m : modules_)
    if (m->fast()) m->drift(*this, ds);
  t_ += ds;
  clock.lap("integration");
  update_neighbours();  // a rebuild may reorder: views are taken anew below
  clock.lap("neighbours");
  update_pair_cache(last ? PairRows::read : PairRows::read_solids);
  if (last) ++configuration_updates_;
  clock.lap("pair_cache");
  fast_forces(ds / dt);
  if (last) slow_forces();
  clock.restart();
  fast_kick(t_);
  clock.lap("integration");
}

template <int D>
void Simulation<D>::advance_multi_rate(double stop) {
  const double rest = stop - t_;
  const double dt = rest <= dt_ ? rest : rest < 2 * dt_ ? 0.5 * rest : dt_;
  const int kappa = kappa_;
  const double ds = dt / kappa, t0 = t_;
  PassClock clock(pass_seconds_);
  auto slow_kick = [&](double h, double t_bc) {
    auto v = p_.v();
    auto as = p_.template view<V>(kas_);
    const std::size_t n = p_.size();
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) v[i] += h * as[i];
    apply_bc_velocity(t_bc);
    for (auto& m : modules_)
      if (!m->fast()) m->kicked(*this, h);
  };
  slow_kick(0.5 * dt, t0 + 0.5 * dt);
  clock.lap("integration");
  slow_rates(dt);
  clock.lap("rates");
  drift_positions(dt, false, 0.0);
  for (auto& m : modules_)
    if (!m->fast()) m->drift(*this, dt);
  clock.lap("integration");
  for (int k = 0; k < kappa; ++k) {
    t_ = t0 + k * ds;
    substep(ds, dt, k == kappa - 1);
  }
  t_ = t0 + dt;
  ++step_;
  total_substeps_ += kappa;
  clock.restart();
  slow_kick(0.5 * dt, t_);
  add_fast_acceleration();
  compute_reactions();
  clock.lap("integration");
  check_guards();
  dt_ = compute_dt_multi_rate();
  clock.lap("guards_and_dt");
  check_dt_collapse();
}

// The step of the slow forces and the sub-step of the fast ones: the acoustic and force limits
// of single-rate stepping, the solids' with a_fast (sub-step) and a_slow (step); the modules'
// own limits by their kind. kappa = ceil(dt/ds) up to time_step.max_substeps.
template <int D>
double Simulation<D>::compute_dt_multi_rate() {
  auto v = p_.v();
  auto as = p_.template view<V>(kas_);
  auto af = p_.template view<V>(kaf_);
  auto mt = p_.material();
  auto ph = p_.phase();
  const std::size_t n = owned();
  const double h = kernel_.h();
  const auto& c = wave_speed_;
  const double inf = std::numeric_limits<double>::infinity();
  double fa = inf, ff = inf, sa = inf, sf = inf;  // fast/slow acoustic and force limits
#pragma omp parallel for reduction(min : fa, ff, sa, sf) schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const bool solid = ph[i] == kSolid;
    // Walls and rigid particles carry no waves (a wall may have a solid's material).
    const bool waves = ph[i] == kSolid || ph[i] == kFluid;
    const double ac = h / ((waves ? c[mt[i]] : 0.0) + v[i].norm());
    if (solid) fa = std::min(fa, ac);
    if (!solid) sa = std::min(sa, ac);
    const double an = as[i].norm(), fn = solid ? af[i].norm() : 0.0;
    if (an > 0) sf = std::min(sf, std::sqrt(h / an));
    if (fn > 0) ff = std::min(ff, std::sqrt(h / fn));
  }
  double ds = std::min(scene_.cfl * fa, scene_.force_factor * ff);
  double dt = std::min(scene_.cfl * sa, scene_.force_factor * sf);
  for (auto& m : modules_) {
    double& limit = m->fast() ? ds : dt;
    limit = std::min(limit, m->max_dt(*this));
  }
  if (scene_.max_dt > 0) dt = std::min(dt, scene_.max_dt);
  ds = comm_.min(ds);
  dt = comm_.min(dt);
  const double ratio = std::ceil(dt / ds * (1 - 1e-12));
  kappa_ = static_cast<int>(std::clamp(ratio, 1.0, double(scene_.max_substeps)));
  return std::min(dt, kappa_ * ds);
}

#define MONOSPH_MULTI_RATE(D)                                 \
  template void Simulation<D>::init_multi_rate();             \
  template void Simulation<D>::fast_forces(double);           \
  template void Simulation<D>::slow_forces();                 \
  template void Simulation<D>::slow_rates(double);            \
  template void Simulation<D>::substep(double, double, bool); \
  template void Simulation<D>::advance_multi_rate(double);    \
  template double Simulation<D>::compute_dt_multi_rate();
MONOSPH_MULTI_RATE(2)
MONOSPH_MULTI_RATE(3)
#undef MONOSPH_MULTI_RATE

}  // namespace monosph
