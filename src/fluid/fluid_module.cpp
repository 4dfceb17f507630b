#include "fluid_module.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "core/sph_equations.hpp"
#include "shifting_terms.hpp"

namespace monosph {

namespace {

// Smallest eigenvalue of a symmetric D x D matrix (the free-surface indicator lambda).
template <int D>
double min_eigenvalue(const Mat<D>& b) {
  using M = Eigen::Matrix<double, D, D>;
  const M s = 0.5 * (M(b) + M(b).transpose());
  if constexpr (D == 2) {
    const double t = 0.5 * s.trace(), det = s.determinant();
    return t - std::sqrt(std::max(0.0, t * t - det));
  } else {
    Eigen::SelfAdjointEigenSolver<M> es;
    es.computeDirect(s, Eigen::EigenvaluesOnly);
    return es.eigenvalues().minCoeff();
  }
}

}  // namespace

template <int D>
FluidModule<D>::FluidModule(Simulation<D>& sim) {
  auto& p = sim.particles();
  kpw_ = p.add_field("wall_pressure", 1);       // Adami p_w of wall-like particles
  kvw_ = p.add_field("wall_velocity", D);       // smoothed fluid velocity at wall-like particles
  kgrad_ = p.add_field("density_gradient", D);  // renormalised <grad rho>^L of fluid particles
  klam_ =
      p.add_field("free_surface", 1, FieldType::Real, true);  // lambda: ~1 inside, < 0.4 surface
  kshift_ = p.add_field("shift_rate", D);                     // delta-plus shift / dt
  kff_ = p.add_field("fluid_force", D, FieldType::Real,
                     true);  // force of the fluid on a wall-like particle
  p.set_meaning({kgrad_, klam_, kshift_}, phase_bit(kFluid));
  p.set_meaning({kpw_, kvw_, kff_}, ~phase_bit(kFluid));  // wall-like particles
  for (const auto& b : sim.bodies()) any_wall_ = any_wall_ || b.phase == kWall;
  // Viscous form: Morris et al. 1997 (default) or the central 2 (d + 2) nu pi_ij of Sun et al.
  // 2017, which conserves angular momentum. A scene with rigid clusters needs the central form:
  // Morris's pair forces along v_ij put a spurious torque on a grain (a free cylinder in shear
  // turned at 1.77 gamma/2 instead of 0.95; cases/couette_cylinder).
  bool any_rigid = false;
  for (const auto& b : sim.bodies()) any_rigid = any_rigid || b.phase == kRigid;
  for (const auto& b : sim.bodies()) keys_.push_back(module_params<FluidBodyKeys>(b.params));
  for (std::size_t i = 0; i < keys_.size(); ++i) {
    const FluidBodyKeys& k = keys_[i];
    if (sim.bodies()[i].phase == kFluid)
      central_ = central_ || k.viscous_form == "central" || (k.viscous_form == "auto" && any_rigid);
    any_shift_ = any_shift_ || k.shift_speed > 0 || k.shift_pb > 0;
    any_consistent_ = any_consistent_ || k.shift_consistent;
  }
  if (any_wall_) {
    kaw_ = p.add_field("wall_acceleration", D);
    kvprev_ = p.add_field("wall_previous_velocity", D);
  }
  for (std::size_t b = 0; b < sim.bodies().size(); ++b) gb_.push_back(sim.body_force(int(b)));
  for (const auto& m : sim.materials()) {
    c0_.push_back(m.sound_speed());
    rho0_.push_back(m.density);
    nu_.push_back(m.viscosity / m.density);
    eos_.push_back(module_params<FluidMaterial>(m.params));
  }
}

template <int D>
void FluidModule<D>::on_create(Simulation<D>& sim) {
  if (kvprev_ < 0) return;
  auto& p = sim.particles();
  auto v = p.v();
  auto vp = p.template view<Vec<D>>(kvprev_);
  for (std::size_t i = 0; i < p.size(); ++i) vp[i] = v[i];
}

template <int D>
void FluidModule<D>::sums(Simulation<D>& sim) {
  auto& p = sim.particles();
  auto x = p.x();
  const auto& pl = sim.pairs();
  const auto& vol = sim.volumes();
  const auto& mats = sim.materials();
  auto ph = p.phase();
  auto rho = p.rho();
  auto pr = p.p();
  auto v = p.v();
  auto a = p.a();
  auto mt = p.material();
  auto pw = p.template view<double>(kpw_);
  auto vw = p.template view<Vec<D>>(kvw_);
  auto grad = p.template view<Vec<D>>(kgrad_);
  auto lam = p.template view<double>(klam_);
  std::span<Vec<D>> aw;
  if (kaw_ >= 0) aw = p.template view<Vec<D>>(kaw_);
  auto bd = p.body();
  // Velocity gradient of the rigid motion of cluster particles (set by the clusters module).
  const int kgrad_rigid = p.find("rigid_velocity_gradient");
  const bool kG = kgrad_rigid >= 0;
  std::span<Mat<D>> G;
  if (kG) G = p.template view<Mat<D>>(kgrad_rigid);
  const std::vector<Vec<D>>& gb = gb_;
  const std::size_t n = p.size();
#pragma omp parallel for schedule(runtime)
  for (std::size_t i = 0; i < n; ++i)
    if (ph[i] == kFluid)  // p = c0^2 (rho - rho0) (Sun Eq. 2), not below cavitation, + p_b
      pr[i] = eos_[mt[i]].pressure(mats[mt[i]], rho[i]);
#pragma omp parallel for schedule(runtime)
  for (std::size_t i = 0; i < n; ++i) {
    if (ph[i] == kFluid) {
      Mat<D> bf = Mat<D>::Zero(), ba = Mat<D>::Zero();
      Vec<D> graw = Vec<D>::Zero();
      const auto row = pl.row(x, i);
      for (std::size_t k = pl.begin(i); k < pl.end(i); ++k) {
        const int j = pl.j[k];
        const Vec<D> r = row.r(k);
        const double f = vol[j] * pl.f[k];
        const Mat<D> rr = -f * (r * r.transpose());  // V_j (x_j - x_i) (x) grad_i W_ij
        ba += rr;
        if (ph[j] != kFluid) continue;
        bf += rr;
        graw += (rho[j] - rho[i]) * f * r;
      }
      // Renormalised density gradient over fluid neighbours (Antuono et al. 2010, equations.md
      // 3.2); lambda over all neighbours, so that fluid next to a wall is not a free surface.
      grad[i] = invert_correction<D>(bf) * graw;
      lam[i] = min_eigenvalue<D>(ba);
    } else {
      // Adami et al. 2012, Eq. 27-28: p_w = [sum_f p_f W + (g - a_w) . sum_f rho_f r_wf W] /
      // sum_f W.
      double sw = 0, sp = 0;
      Vec<D> srw = Vec<D>::Zero(), sv = Vec<D>::Zero();
      const auto row = pl.row(x, i);
      for (std::size_t k = pl.begin(i); k < pl.end(i); ++k) {
        const int j = pl.j[k];
        if (ph[j] != kFluid) continue;
        const double w = pl.w[k];
        const Vec<D> r = row.r(k);  // r_wf = x_w - x_f
        sw += w;
        sp += (pr[j] + rho[j] * gb[bd[j]].dot(r)) * w;  // g of the fluid's body
        srw += (rho[j] * w) * r;
        // The fluid velocity relative to the body's own motion field carried to x_w: a rigid
        // cluster rotates (G = skew(omega)), so v_f - G (x_f - x_w) = v_f + G r. Adami's smoothed
        // velocity assumes a uniform wall velocity over the support; for a rotating grain that
        // assumption made a free cylinder in shear spin at 1.9 gamma/2 instead of gamma/2.
        sv += w * (kG ? Vec<D>(v[j] + G[i] * r) : Vec<D>(v[j]));
      }
      if (sw > 0) {
        // The wall's acceleration: prescribed motion (walls) or the last step's (solid, rigid).
        const Vec<D> ai = ph[i] == kWall ? aw[i] : a[i];
        pw[i] = (sp - ai.dot(srw)) / sw;
        // `wall_pressure: non_negative`: no suction at free surfaces, where a negative p_w holds
        // fluid particles on the wall (sticking; cases/stability/README.md).
        if (keys_[bd[i]].non_negative_wall_pressure) pw[i] = std::max(pw[i], 0.0);
        vw[i] = sv / sw;
      } else {
        pw[i] = 0;
        vw[i] = v[i];
      }
      lam[i] = 1;
    }
  }
  sim.exchange({kgrad_, klam_, kpw_, kvw_});  // read through neighbours in rates and forces
  if (!surface_checked_) check_no_free_surface(sim);
}

template <int D>
void FluidModule<D>::check_no_free_surface(Simulation<D>& sim) {
  // A background pressure pushes a free surface outwards (its particles lack the neighbours
  // whose p_b would balance their own): a scene with one is an input error, found on the
  // lattice at t = 0 by lambda (about 1 inside and at walls, 0.4-0.7 on a lattice's free
  // surface). A restart (t > 0, disordered particles) is not checked again.
  surface_checked_ = true;
  if (sim.time() > 0) return;
  auto& p = sim.particles();
  auto ph = p.phase();
  auto mt = p.material();
  auto lam = p.template view<double>(klam_);
  const auto& mats = sim.materials();
  std::vector<double> count(mats.size(), 0.0);
  for (std::size_t i = 0; i < sim.owned(); ++i)
    if (ph[i] == kFluid && eos_[mt[i]].background_pressure > 0 && lam[i] < 0.75) count[mt[i]] += 1;
  sim.comm().sum(count);
  for (std::size_t k = 0; k < mats.size(); ++k)
    if (count[k] > 0)
      throw InputError(fmt::format(
          "materials.{}.background_pressure: the fluid has a free surface ({:g} particles with "
          "lambda < 0.75 at t = 0); a background pressure is for flows without one",
          mats[k].name, count[k]));
}

template <int D>
void FluidModule<D>::rates(Simulation<D>& sim) {
  auto& p = sim.particles();
  auto x = p.x();
  const auto& pl = sim.pairs();
  const auto& vol = sim.volumes();
  const auto& bodies = sim.bodies();
  auto ph = p.phase();
  auto rho = p.rho();
  auto drho = p.drho();
  auto v = p.v();
  auto mt = p.material();
  auto bd = p.body();
  auto grad = p.template view<Vec<D>>(kgrad_);
  auto du = p.template view<Vec<D>>(kshift_);  // shift velocity (zero on wall-like particles)
  const double h = sim.kernel().h();
  const std::size_t n = p.size();
#pragma omp parallel for schedule(runtime)
  for (std::size_t i = 0; i < n; ++i) {
    if (ph[i] != kFluid) continue;  // walls keep drho = 0 (nothing writes it)
    const double delta = bodies[bd[i]].delta;
    const bool ale = keys_[bd[i]].shift_consistent;
    double div = 0, diff = 0, ale_rate = 0;
    const auto row = pl.row(x, i);
    for (std::size_t k = pl.begin(i); k < pl.end(i); ++k) {
      const int j = pl.j[k];
      const Vec<D> r = row.r(k);
      const double f = pl.f[k], vj = vol[j];
      div += vj * f * (v[j] - v[i]).dot(r);  // wall-like j: its own (body) velocity
      if (delta > 0 && ph[j] == kFluid)
        // psi_ji . grad_i W_ij with psi_ji = 2 (rho_j - rho_i) r_ji / r^2 - (<grad rho>_i +
        // <grad rho>_j): zero for a linear density field (Antuono et al. 2012).
        diff += vj * f * (-2.0 * (rho[j] - rho[i]) - (grad[i] + grad[j]).dot(r));
      // Sun et al. 2019: the particle moves at v + du (shifting_terms.hpp).
      if (ale) ale_rate += ale_continuity_pair<D>(rho[i], rho[j], du[i], du[j], f * r, vj);
    }
    // Sun et al. 2017, Eq. 3: continuity with the delta-SPH diffusive term.
    drho[i] = -rho[i] * div + delta * h * c0_[mt[i]] * diff + ale_rate;
  }
  sim.exchange({p.find("density_rate")});
}

template <int D>
void FluidModule<D>::forces(Simulation<D>& sim) {
  auto& p = sim.particles();
  auto x = p.x();
  const auto& pl = sim.pairs();
  const auto& vol = sim.volumes();
  const auto& bodies = sim.bodies();
  const auto& W = sim.kernel();
  auto ph = p.phase();
  auto rho = p.rho();
  auto pr = p.p();
  auto v = p.v();
  auto a = p.a();
  auto m = p.m();
  auto mt = p.material();
  auto bd = p.body();
  auto pw = p.template view<double>(kpw_);
  auto vw = p.template view<Vec<D>>(kvw_);
  auto ff = p.template view<Vec<D>>(kff_);
  const double h = W.h(), eta2 = 0.01 * h * h;
  const std::size_t n = p.size();
  // Physical viscosity: Morris et al. 1997, a_i = 2 nu (rho0/rho_i) sum_j V_j F_ij v_ij (with
  // r^2/(r^2 + 0.01 h^2)); artificial: delta-SPH alpha h c0 (rho0/rho_i) sum_j pi_ij grad W V_j.
  // The Morris form follows the exact decay of the Taylor-Green vortex within 0.9 % at 100^2,
  // the 2(d + 2) nu pi_ij form of Sun 2017 within 2.1 % (cases/taylor_green/README.md); that
  // one conserves angular momentum and is used with rigid clusters (central_).
  auto nu_of = [&](std::size_t i) { return 2.0 * nu_[mt[i]]; };
  auto alpha_of = [&](std::size_t i) { return bodies[bd[i]].av_alpha * h * c0_[mt[i]]; };
  // Monaghan's quadratic term (Monaghan 1992; the beta term of MMB Eq. 17-18: beta mu_ij^2, mu_ij =
  // h v_ij.r_ij / (r^2 + 0.01 h^2)), on closing pairs only: negligible at flow speeds << c0, it
  // keeps fast jets from passing through each other (artificial_viscosity.beta of a fluid body).
  auto beta_of = [&](std::size_t i) { return bodies[bd[i]].av_beta * h * h; };
  // The viscous terms of pair (i, j) with the velocity vj of j, as an acceleration factor.
  auto viscous = [&](double nu, double al, double be, double vol_j, double f, const Vec<D>& r,
                     const Vec<D>& vij) {
    const double r2 = r.squaredNorm(), q = 1.0 / (r2 + eta2), vr = vij.dot(r);
    if (vr < 0) al -= be * vr * q;
    return Vec<D>(vol_j * f * (nu * r2 * q * vij + (al * vr * q) * r));
  };
  if (any_shift_) shift_velocities(sim);  // before the pair loop: the ALE terms read du_j
  auto du = p.template view<Vec<D>>(kshift_);
#pragma omp parallel for schedule(runtime)
  for (std::size_t i = 0; i < n; ++i) {
    if (ph[i] == kFluid) {
      const FluidBodyKeys& b = keys_[bd[i]];
      const double nui = nu_of(i), ali = alpha_of(i);
      Vec<D> ap = Vec<D>::Zero(), av = Vec<D>::Zero(), ale = Vec<D>::Zero();
      const auto row = pl.row(x, i);
      for (std::size_t k = pl.begin(i); k < pl.end(i); ++k) {
        const int j = pl.j[k];
        const Vec<D> r = row.r(k);
        const Vec<D> gw = pl.f[k] * r;  // grad_i W_ij
        const double vj = vol[j];
        const bool fj = ph[j] == kFluid;
        // Sun et al. 2017, Eq. 3: -(1/rho_i) sum_j (p_i + p_j) grad W V_j; a wall-like j enters
        // with its extrapolated pressure and its own (geometric) volume (Adami et al. 2012).
        ap -= ((pr[i] + (fj ? pr[j] : pw[j])) * vj) * gw;
        if (fj || keys_[bd[j]].no_slip) {
          // pi_ij = v_ij . r_ij / (r^2 + 0.01 h^2); at a no-slip wall v_j -> 2 v_w - v~_w.
          const Vec<D> vjv = fj ? Vec<D>(v[j]) : Vec<D>(2.0 * v[j] - vw[j]);
          double nu = fj ? 0.5 * (nui + nu_of(j)) : nui;
          double al = fj ? 0.5 * (ali + alpha_of(j)) : ali;
          if (central_) al += (D + 2) * nu, nu = 0;  // 2 (d + 2) nu pi_ij (Sun 2017)
          const double be = fj ? 0.5 * (beta_of(i) + beta_of(j)) : beta_of(i);
          av += viscous(nu, al, be, vj, pl.f[k], r, v[i] - vjv);
        }
        // Sun et al. 2019: (du . grad) v of a particle moving at v + du (shifting_terms.hpp).
        if (b.shift_consistent) ale += ale_momentum_pair<D>(v[i], v[j], du[i], du[j], gw, vj);
      }
      a[i] += ap / rho[i] + (rho0_[mt[i]] / rho[i]) * av + ale;
    } else {
      // The reaction of every fluid-pair force above (exactly opposite): force on particle i.
      Vec<D> f = Vec<D>::Zero();
      const bool noslip = keys_[bd[i]].no_slip;
      const auto row = pl.row(x, i);
      for (std::size_t k = pl.begin(i); k < pl.end(i); ++k) {
        const int j = pl.j[k];
        if (ph[j] != kFluid) continue;
        const Vec<D> r = row.r(k);
        const Vec<D> gw = pl.f[k] * r;  // grad_i W_ij = -grad_j W_ji
        const double vv = vol[i] * vol[j];
        f -= ((pr[j] + pw[i]) * vv) * gw;
        if (noslip) {  // minus the viscous force on j: rho0 V_j V_i (pair term of j)
          const Vec<D> viv = 2.0 * v[i] - vw[i];
          f -= rho0_[mt[j]] * vol[j] *
               (central_
                    ? viscous(0.0, alpha_of(j) + (D + 2) * nu_of(j), beta_of(j), vol[i], pl.f[k], r,
                              v[j] - viv)
                    : viscous(nu_of(j), alpha_of(j), beta_of(j), vol[i], pl.f[k], r, v[j] - viv));
        }
      }
      ff[i] = f;
      if (ph[i] == kWall)
        a[i].setZero();  // walls move as prescribed (initial velocity, boundary conditions)
      else
        a[i] += f / m[i];
    }
  }
}

template <int D>
void FluidModule<D>::shift_velocities(Simulation<D>& sim) {
  auto& p = sim.particles();
  auto x = p.x();
  const auto& pl = sim.pairs();
  const auto& vol = sim.volumes();
  auto ph = p.phase();
  auto rho = p.rho();
  auto bd = p.body();
  auto lam = p.template view<double>(klam_);
  auto shift = p.template view<Vec<D>>(kshift_);
  const double h = sim.kernel().h(), wdp = sim.kernel().w(sim.dp()), dt = sim.dt();
  const std::size_t n = p.size();
#pragma omp parallel for schedule(runtime)
  for (std::size_t i = 0; i < n; ++i) {
    if (ph[i] != kFluid) continue;
    const FluidBodyKeys& b = keys_[bd[i]];
    Vec<D> sh = Vec<D>::Zero(), gl = Vec<D>::Zero(), tv = Vec<D>::Zero();  // gl: sum V_j grad W
    bool near_surface = lam[i] <= 0.75;
    const bool on = b.shift_speed > 0 || b.shift_pb > 0;
    const auto row = pl.row(x, i);
    for (std::size_t k = pl.begin(i); on && k < pl.end(i); ++k) {
      const int j = pl.j[k];
      const Vec<D> gw = pl.f[k] * row.r(k);  // grad_i W_ij
      const double vj = vol[j];
      if (b.shift_speed > 0) {
        const double q = pl.w[k] / wdp, q2 = q * q;  // (W/W(dp))^n; n = 4 without pow
        sh += (1.0 + b.shift_R * (b.shift_n == 4 ? q2 * q2 : std::pow(q, b.shift_n))) * vj * gw;
      }
      tv += transport_pair<D>(vol[i], vj, gw);
      gl += vj * gw;  // towards the filled side (fluid and walls): minus the surface normal
      near_surface = near_surface || (ph[j] == kFluid && lam[j] < 0.4);
    }
    // delta-plus shifting (Sun et al. 2017, Eq. 7-9): dr = -CFL Ma (2h)^2 sum[..] grad W V_j with
    // CFL = c0 dt / h and Ma = U / c0, i.e. dr = -4 h U dt sum[..]; stored per unit dt.
    // Transport velocity (Adami, Hu & Adams 2013, the background-pressure term of the transport
    // velocity, applied over their half-step kick): du_i = -(dt/2) (p_b / m_i) sum_j (V_i^2 +
    // V_j^2) grad W_ij, m_i = rho_i V_i; dt is the last step (0 before the first).
    Vec<D> s = Vec<D>::Zero();
    if (on && lam[i] >= 0.4) {
      s = b.shift_speed > 0 ? Vec<D>(-4.0 * h * b.shift_speed * sh)
                            : Vec<D>((-0.5 * dt * b.shift_pb / (rho[i] * vol[i])) * tv);
      // Near the surface (lambda <= 0.75, or a neighbour of a surface particle): tangential part
      // only, so that no particle is pushed through the surface (or up a wall).
      if (near_surface && gl.squaredNorm() > 0) {
        const Vec<D> nn = gl.normalized();
        s -= s.dot(nn) * nn;
      }
    }
    shift[i] = s;
  }
  sim.exchange({kshift_});  // ghosts shift in drift as their owners do; ALE terms read du_j
}

template <int D>
void FluidModule<D>::drift(Simulation<D>& sim, double dt) {
  auto& p = sim.particles();
  auto ph = p.phase();
  auto x = p.x();
  auto v = p.v();
  auto shift = p.template view<Vec<D>>(kshift_);
  const double cap = 0.1 * sim.dp();  // safety net, not part of Sun et al.: |dr| <= 0.1 dp
  std::span<Vec<D>> aw, vp;
  if (kaw_ >= 0) aw = p.template view<Vec<D>>(kaw_), vp = p.template view<Vec<D>>(kvprev_);
  const std::size_t n = p.size();
#pragma omp parallel for schedule(runtime)
  for (std::size_t i = 0; i < n; ++i) {
    if (ph[i] == kFluid) {
      Vec<D> d = dt * shift[i];
      const double len = d.norm();
      if (len > cap) d *= cap / len;
      x[i] += d;
    } else if (ph[i] == kWall) {  // centred difference of the prescribed velocity
      aw[i] = (v[i] - vp[i]) / dt;
      vp[i] = v[i];
    }
  }
}

template <int D>
double FluidModule<D>::max_dt(Simulation<D>& sim) {
  // Viscous limit dt <= 0.125 h^2 / nu (Morris et al. 1997, Eq. 23); the acoustic and force
  // limits are the core's (the fluid's wave speed is c0). The central form 2 (d + 2) nu pi_ij is
  // nu lap v + 2 nu grad div v (Espanol & Revenga 2003): its longitudinal modes diffuse with 3 nu,
  // so its limit is a third of Morris's. On a square lattice the largest eigenvalue of the
  // discrete operator (the explicit velocity update is stable for dt lambda < 2) is, in nu/dp^2,
  // cubic spline h = 1.3 dp: 3.35 Morris, 9.33 central; Wendland C2: 3.66, 10.1. At 0.125 h^2/nu
  // the central form was unstable with Wendland (a free cylinder in shear blew up) and marginal
  // with the cubic spline (dt lambda = 1.97; docs/studies/couette).
  double nu = 0;
  for (double x : nu_) nu = std::max(nu, x);
  if (nu <= 0) return std::numeric_limits<double>::infinity();
  const double h = sim.kernel().h();
  return 0.125 * h * h / nu / (central_ ? 3.0 : 1.0);
}

template <int D>
std::vector<std::string> FluidModule<D>::probe_columns(const ProbeSpec& s) const {
  if (s.type != "fluid_force") return {};
  return axis_columns(D);
}

template <int D>
void FluidModule<D>::probe(Simulation<D>& sim, const ProbeSpec& s, std::vector<double>& out) {
  // Total force of the fluid on the particles of `body` (all wall-like particles without one).
  auto& p = sim.particles();
  auto bd = p.body();
  auto ff = p.template view<Vec<D>>(kff_);
  auto ph = p.phase();
  int body = -1;
  for (std::size_t b = 0; b < sim.bodies().size(); ++b)
    if (sim.bodies()[b].name == s.body) body = static_cast<int>(b);
  Vec<D> f = Vec<D>::Zero();
  for (std::size_t i = 0; i < sim.owned(); ++i)
    if (ph[i] != kFluid && (body < 0 || bd[i] == body)) f += ff[i];
  sim.comm().sum(std::span<double>(f.data(), D));
  for (int a = 0; a < D; ++a) out.push_back(f[a]);
}

template class FluidModule<2>;
template class FluidModule<3>;

}  // namespace monosph
