#include "solid_module.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/sph_equations.hpp"
#include "elasticity.hpp"
#include "plasticity.hpp"

namespace monosph {

namespace {
inline bool is_solid(std::int64_t ph) {
  return ph == kSolid;
}
}  // namespace

template <int D>
SolidModule<D>::SolidModule(Simulation<D>& sim) {
  for (const auto& b : sim.bodies()) keys_.push_back(module_params<SolidBodyKeys>(b.params));
  for (const auto& m : sim.materials()) mat_.push_back(module_params<SolidMaterial>(m.params));
  auto& p = sim.particles();
  kS_ = p.add_field("deviatoric_stress", 9);
  kvm_ = p.add_field("von_mises", 1, FieldType::Real, true);
  kX0_ = p.add_field("initial_position", D);
  kXref_ = p.add_field("reference_position", D);
  kF_ = p.add_field("deformation_gradient", D * D);
  kFref_ = p.add_field("incremental_deformation", D * D);
  kFinit_ = p.add_field("reference_deformation", D * D);
  kdis_ = p.add_field("disorder", 1, FieldType::Real, true);
  kgradv_ = p.add_field("velocity_gradient", D * D);
  for (std::size_t i = 0; i < keys_.size(); ++i) {
    any_as_ = any_as_ || sim.bodies()[i].as_epsilon > 0;
    any_ls_ = any_ls_ || (sim.bodies()[i].phase == kSolid && keys_[i].hg_reference == 2);
  }
  if (any_ls_) kFls_ = p.add_field("fitted_deformation", D * D);
  bool any_springs = false;
  for (const auto& k : keys_) any_springs = any_springs || (k.hg_xi > 0 && k.hg_chi < 1);
  // Energy in the hourglass springs: part of the scheme's stored energy (total_energy probe).
  if (any_springs) khge_ = p.add_field("hourglass_energy", 1);
  for (const auto& b : sim.bodies()) {
    if (b.phase != kSolid) continue;
    if (b.formulation == 2 && klap_ < 0)  // Zhang et al. 2024, Eq. 20
      klap_ = p.add_field("shear_laplacian_integral", D);
    const SolidMaterial& m = mat_[b.material];
    any_plastic_ = any_plastic_ || m.plasticity.on;
    any_damage_ = any_damage_ || m.damage.on;
    const SolidBodyKeys& k = keys_[&b - sim.bodies().data()];
    any_erosion_ = any_erosion_ || (m.damage.on && k.erosion > 0);
    any_self_contact_ = any_self_contact_ || k.self_contact > 0;
  }
  if (any_plastic_) {
    kep_ = p.add_field("plastic_strain", 1, FieldType::Real, true);
    kepr_ = p.add_field("plastic_strain_rate", 1, FieldType::Real, true);
    kT_ = p.add_field("temperature", 1, FieldType::Real, true);
    ksy_ = p.add_field("yield_stress", 1, FieldType::Real, true);
    kwp_ = p.add_field("plastic_work", 1, FieldType::Real, true);  // sigma_y deps V, summed
  }
  if (any_damage_) {
    kdmg_ = p.add_field("damage", 1, FieldType::Real, true);
    kfail_ = p.add_field("failure_energy", 1, FieldType::Real, true);
  }
  for (const auto& m : sim.materials()) {
    const double l = mat_[&m - sim.materials().data()].damage.nonlocal_length;
    if (l <= 0) continue;
    const std::string key = "materials." + m.name + ".damage.nonlocal_length";
    if (l <= sim.dp())
      throw InputError(key +
                       ": must exceed the particle spacing dp (an average over one particle "
                       "is the local damage)");
    if (sim.comm().size() > 1) throw InputError(key + ": non-local damage runs on one rank");
    any_nonlocal_ = true;
  }
  if (any_as_) kas_ = p.add_field("artificial_stress", D * D);
  // Frames: NaN off solid particles; deformation gradients pad to F_zz = 1 in 2D (plane strain).
  p.set_meaning({kS_, kvm_, kX0_, kXref_, kdis_, khge_, klap_, kep_, kepr_, kT_, ksy_, kwp_, kdmg_,
                 kfail_, kas_},
                phase_bit(kSolid));
  p.set_meaning({kF_, kFref_, kFinit_, kFls_}, phase_bit(kSolid), 1.0);
  bool any_tl = false;
  for (const auto& b : sim.bodies()) any_tl = any_tl || (b.phase == kSolid && b.total_lagrangian);
  if (any_tl) tl_ = std::make_unique<TotalLagrangian<D>>(sim, kS_, kF_, kgradv_, kX0_, kep_, ksy_);
  // Pair rows read: those of every solid body; of a total-Lagrangian body (whose forces use its
  // reference pairs) only for self-contact, surface erosion or a fitted deformation (sums).
  for (std::size_t b = 0; b < keys_.size(); ++b) {
    const SolidBodyKeys& k = keys_[b];
    const bool tl = tl_ && tl_->is_tl(std::int64_t(b));
    rows_.push_back(sim.bodies()[b].phase == kSolid &&
                    (!tl || k.self_contact > 0 || k.erosion == 2 || any_ls_));
  }
  const auto& dom = sim.neighbours().domain();
  const Vec<D> len = dom.length();
  for (int a = 0; a < D; ++a) period_[a] = dom.periodic[a] ? len[a] : 0.0;
}

template <int D>
void SolidModule<D>::on_create(Simulation<D>& sim) {
  auto& p = sim.particles();
  auto x = p.x();
  auto X0 = p.template view<Vec<D>>(kX0_);
  auto Fi = p.template view<Mat<D>>(kFinit_);
  auto F = p.template view<Mat<D>>(kF_);
  for (std::size_t i = 0; i < p.size(); ++i) {
    X0[i] = x[i];
    Fi[i] = Mat<D>::Identity();
    F[i] = Mat<D>::Identity();
  }
  if (tl_) tl_->on_create(sim);
  if (!any_plastic_) return;
  auto T = p.template view<double>(kT_);
  auto sy = p.template view<double>(ksy_);
  auto bd = p.body();
  const auto& bodies = sim.bodies();
  for (std::size_t i = 0; i < p.size(); ++i) {
    const BodyInfo& b = bodies[bd[i]];
    const Material& mat = sim.materials()[b.material];
    T[i] = mat.initial_temperature(b.temperature);
    const JohnsonCook& jc = mat_[b.material].plasticity;
    sy[i] = jc.on ? jc_yield(jc, 0, 0, T[i]) : 0;
  }
}

template <int D>
void SolidModule<D>::drift(Simulation<D>& sim, double dt) {
  // S_{n+1} from the velocity gradient of the half-step velocities (SphEquations::rates).
  auto& p = sim.particles();
  auto ph = p.phase();
  auto mt = p.material();
  auto S = p.template view<Mat3>(kS_);
  auto L = p.template view<Mat<D>>(kgradv_);
  const auto& mats = sim.materials();
  const std::size_t n = p.size();
  // Hypoelastic stress of both formulations; neo-Hookean S comes from F (constitutive).
#pragma omp parallel for schedule(runtime)
  for (std::size_t i = 0; i < n; ++i)
    if (is_solid(ph[i]) && !mat_[mt[i]].neo_hookean)
      S[i] = update_deviatoric(S[i], pad33<D>(L[i]), mats[mt[i]].shear_modulus, dt);
  if (klap_ >= 0) {  // I_i += dt dI_i/dt (laplacian_rate)
    auto I = p.template view<Vec<D>>(klap_);
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < lap_rate_.size(); ++i) I[i] += dt * lap_rate_[i];
  }
  if (any_plastic_) plastic_return(sim, dt);
  if (any_erosion_) erode(sim);
}

template <int D>
void SolidModule<D>::laplacian_rate(Simulation<D>& sim) {
  // Zhang et al. 2024, Eq. 19-20: I_i += dt sum_j (e_ij . v_ij / r_ij) grad_i W_ij V_j with the
  // half-step velocities and the pairs of the last force pass (the midpoint rule over the step,
  // as the stress update); `drift` adds it. The shear acceleration 2 zeta G / rho_i I_i is added
  // in `forces`.
  auto& p = sim.particles();
  const auto& pl = sim.pairs();
  const auto& grp = sim.group();
  const auto& vol = sim.volumes();
  auto ph = p.phase();
  auto bd = p.body();
  auto v = p.v();
  auto x = p.x();
  const auto& bodies = sim.bodies();
  const std::size_t n = std::min(p.size(), pl.count.size());
  lap_rate_.resize(n);  // every row set below
#pragma omp parallel for schedule(runtime)
  for (std::size_t i = 0; i < n; ++i) {
    if (!is_solid(ph[i]) || bodies[bd[i]].formulation != 2) {
      lap_rate_[i] = Vec<D>::Zero();
      continue;
    }
    Vec<D> lap = Vec<D>::Zero();
    for (std::size_t k = pl.begin(i); k < pl.end(i); ++k) {
      const int j = pl.j[k];
      if (grp[j] != grp[i] || !is_solid(ph[j])) continue;
      const Vec<D> r = pl.r(x, i, k);  // x_i - x_j = r_ij e_ij
      lap += (vol[j] * pl.f[k] * r.dot(v[i] - v[j]) / r.squaredNorm()) * r;  // f r = grad_i W
    }
    lap_rate_[i] = lap;
  }
}

template <int D>
void SolidModule<D>::plastic_return(Simulation<D>& sim, double dt) {
  auto& p = sim.particles();
  auto ph = p.phase();
  auto mt = p.material();
  auto rho = p.rho();
  auto S = p.template view<Mat3>(kS_);
  auto ep = p.template view<double>(kep_);
  auto epr = p.template view<double>(kepr_);
  auto T = p.template view<double>(kT_);
  auto sy = p.template view<double>(ksy_);
  auto wp = p.template view<double>(kwp_);
  std::span<double> dmg, fail;
  if (kdmg_ >= 0) dmg = p.template view<double>(kdmg_), fail = p.template view<double>(kfail_);
  auto m = p.m();
  const auto& mats = sim.materials();
  const std::size_t n = p.size();
  if (any_nonlocal_) dmg_inc_.assign(n, 0.0);
    // Dynamic chunks: the yielding particles (a Newton solve each) gather in one region, e.g. the
    // impact end of a Taylor bar, which equal halves would give to one thread.
#pragma omp parallel for schedule(dynamic, 256)
  for (std::size_t i = 0; i < n; ++i) {
    if (!is_solid(ph[i])) continue;
    if (!mat_[mt[i]].plasticity.on) continue;
    PlasticPoint pt{ep[i], epr[i], T[i], kdmg_ >= 0 ? dmg[i] : 0.0, sy[i]};
    const bool nonlocal = mat_[mt[i]].damage.nonlocal_length > 0;
    plastic_update(S[i], pt, mats[mt[i]], mat_[mt[i]], rho[i], dt, nonlocal);
    wp[i] += pt.sigma_y * (pt.eps_p - ep[i]) * m[i] / rho[i];  // MMB Eq. 24's plastic work
    ep[i] = pt.eps_p, epr[i] = pt.rate, T[i] = pt.T, sy[i] = pt.sigma_y;
    if (kdmg_ < 0) continue;
    dmg[i] = pt.D;
    fail[i] += pt.released * m[i] / rho[i];
    // At most what the point has left to fail: the floored failure strain (min_failure_strain)
    // gives increments of 1e4 and more in tension, which no average may spread.
    if (nonlocal) dmg_inc_[i] = std::min(pt.dD, 1 - pt.D);
  }
  if (any_nonlocal_) nonlocal_damage(sim);
}

template <int D>
void SolidModule<D>::nonlocal_damage(Simulation<D>& sim) {
  // The increments of this step's returns, averaged over l (nonlocal_damage.hpp), grow D.
  auto& p = sim.particles();
  auto ph = p.phase();
  auto mt = p.material();
  auto rho = p.rho();
  auto m = p.m();
  auto S = p.template view<Mat3>(kS_);
  auto dmg = p.template view<double>(kdmg_);
  auto fail = p.template view<double>(kfail_);
  const std::size_t n = sim.owned();
  dmg_len_.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    if (is_solid(ph[i])) dmg_len_[i] = mat_[mt[i]].damage.nonlocal_length;
  nonlocal_.average(sim, dmg_len_, dmg_inc_, dmg_avg_);
  const auto& mats = sim.materials();
#pragma omp parallel for schedule(runtime)
  for (std::size_t i = 0; i < n; ++i) {
    if (dmg_avg_[i] <= 0) continue;
    PlasticPoint pt;
    pt.D = dmg[i];
    add_damage(S[i], pt, mats[mt[i]], rho[i], dmg_avg_[i]);
    dmg[i] = pt.D;
    fail[i] += pt.released * m[i] / rho[i];
  }
}

template <int D>
void SolidModule<D>::erode(Simulation<D>& sim) {
  // Particles with D >= 1 of bodies that ask for erosion are removed; with `failed_surface` only
  // those on the surface of the intact material: the kernel sum over intact neighbours of the
  // same continuum, sum_j V_j W_ij (j != i), below 3/4 of its value inside a full lattice
  // (about 1 - V_i W(0)); a flat surface gives about half of it.
  auto& p = sim.particles();
  const auto& pl = sim.pairs();
  auto ph = p.phase();
  auto bd = p.body();
  auto dmg = p.template view<double>(kdmg_);
  const auto& grp = sim.group();
  const auto& vol = sim.volumes();
  const double w0 = sim.kernel().w(0.0);
  const std::size_t n = p.size();
  if (pl.count.size() != n || grp.size() != n) return;
  auto& flag = erode_flag_;
  flag.resize(n);
  long count = 0;
#pragma omp parallel for reduction(+ : count) schedule(runtime)
  for (std::size_t i = 0; i < n; ++i) {
    flag[i] = 0;
    if (!is_solid(ph[i]) || dmg[i] < 1) continue;
    const int mode = keys_[bd[i]].erosion;
    if (mode == 0) continue;
    bool remove = mode == 1;
    if (mode == 2) {
      double s = 0;
      for (std::size_t k = pl.begin(i); k < pl.end(i); ++k) {
        const int j = pl.j[k];
        if (grp[j] == grp[i] && is_solid(ph[j]) && dmg[j] < 1) s += vol[j] * pl.w[k];
      }
      remove = s < 0.75 * (1 - vol[i] * w0);
    }
    if (remove) flag[i] = 1, ++count;
  }
  if (count > 0) sim.remove_particles(flag);
}

template <int D>
void SolidModule<D>::constitutive(Simulation<D>& sim) {
  auto& p = sim.particles();
  auto ph = p.phase();
  auto bd = p.body();
  auto rho = p.rho();
  auto pr = p.p();
  auto S = p.template view<Mat3>(kS_);
  auto vm = p.template view<double>(kvm_);
  std::span<Mat<D>> art;
  std::span<double> shep;
  if (any_as_) {
    art = p.template view<Mat<D>>(kas_);
    shep = p.template view<double>("shepard");
  }
  std::span<double> dmg;
  if (kdmg_ >= 0) dmg = p.template view<double>(kdmg_);
  const auto& bodies = sim.bodies();
  const std::size_t n = p.size();
  if (tl_) tl_->constitutive(sim);  // pressure and PK1 of the total-Lagrangian particles
#pragma omp parallel for schedule(runtime)
  for (std::size_t i = 0; i < n; ++i) {
    if (!is_solid(ph[i])) continue;
    // A failed particle (D >= 1) is cracked material: no deviatoric stress (MMB Sect. 2.3) and,
    // beyond MMB, no tension either (p >= 0), or failed neighbours pull each other together.
    if (kdmg_ >= 0 && dmg[i] >= 1 && pr[i] < 0) pr[i] = 0;
    vm[i] = von_mises(S[i]);
    if (any_as_) {
      const double eps = bodies[bd[i]].as_epsilon;
      if (eps > 0) {
        // MMB Eq. 19-20: eps R_i, divided by rho^2 S as the stress term it corrects.
        const Mat<D> sigma =
            Mat<D>(S[i].template topLeftCorner<D, D>()) - pr[i] * Mat<D>::Identity();
        art[i] = eps * tensile_part<D>(sigma) / (rho[i] * rho[i] * shep[i]);
      } else {
        art[i].setZero();
      }
    }
  }
}

template <int D>
void SolidModule<D>::compute_deformation_gradient(Simulation<D>& sim) {
  auto& p = sim.particles();
  auto x = p.x();
  auto ph = p.phase();
  auto F = p.template view<Mat<D>>(kF_);
  auto Fi = p.template view<Mat<D>>(kFinit_);
  auto Fr = p.template view<Mat<D>>(kFref_);
  auto bd = p.body();
  const auto& shift = sim.neighbours().shifts();
  const std::size_t n = p.size();
  if (rstart_.size() != n + 1) return;
#pragma omp parallel for schedule(runtime)
  for (std::size_t i = 0; i < n; ++i) {
    if (!eulerian(ph[i], bd[i])) continue;
    // F_ref = I + sum_j (u_j - u_i) (x) g_ij = sum_j (x_j - x_i) (x) g_ij, because
    // sum_j (X_j - X_i) (x) g_ij = I by construction of the correction (MMB Eq. 28).
    Mat<D> fr = Mat<D>::Zero();
    for (std::size_t k = rstart_[i]; k < rstart_[i + 1]; ++k)
      fr.noalias() += (x[rj_[k]] + shift[rcode_[k]] - x[i]) * rg_[k].transpose();
    Fr[i] = fr;
    F[i] = fr * Fi[i];  // MMB Eq. 30
  }
}

template <int D>
void SolidModule<D>::rates(Simulation<D>& sim) {
  if (tl_) tl_->rates(sim);  // L = Fdot F^-1 (SphEquations::rates skips these particles)
  if (klap_ >= 0) laplacian_rate(sim);
}

template <int D>
void SolidModule<D>::sums(Simulation<D>& sim) {
  compute_deformation_gradient(sim);
  if (tl_) tl_->sums(sim);
  if (any_ls_) fit_deformation(sim, true);
  // The hourglass forces read F_j (and the fit) of neighbours.
  if (any_ls_)
    sim.exchange({kF_, kFls_});
  else
    sim.exchange({kF_});
}

template <int D>
void SolidModule<D>::diagnostics(Simulation<D>& sim) {
  fit_deformation(sim, false);
}

template <int D>
void SolidModule<D>::fit_deformation(Simulation<D>& sim, bool store_fit) {
  auto& p = sim.particles();
  const auto& pl = sim.pairs();
  const auto& pw = pl.w;
  auto ph = p.phase();
  auto bd = p.body();
  auto x = p.x();
  auto X0 = p.template view<Vec<D>>(kX0_);
  auto dis = p.template view<double>(kdis_);
  std::span<Mat<D>> fls;
  if (kFls_ >= 0) fls = p.template view<Mat<D>>(kFls_);
  const double dp = sim.dp();
  const std::size_t n = p.size();
  if (pl.count.size() != n) return;
#pragma omp parallel for schedule(runtime)
  for (std::size_t i = 0; i < n; ++i) {
    if (!is_solid(ph[i])) continue;
    Mat<D> A = Mat<D>::Zero(), B = Mat<D>::Zero();
    double den = 0;
    for (std::size_t k = pl.begin(i); k < pl.end(i); ++k) {
      const int j = pl.j[k];
      if (bd[j] != bd[i]) continue;
      const Vec<D> d = -pl.r(x, i, k);
      const Vec<D> X = initial_difference(X0[j], X0[i]);
      A.noalias() += pw[k] * d * X.transpose();
      B.noalias() += pw[k] * X * X.transpose();
      den += pw[k];
    }
    if (den == 0 || std::abs(Mat<D>(B / den).determinant()) < 1e-12 * std::pow(dp, 2 * D)) {
      dis[i] = 0;
      if (store_fit && kFls_ >= 0) fls[i] = Mat<D>::Identity();
      continue;
    }
    const Mat<D> F = A * Mat<D>(B.inverse());
    double res = 0;
    for (std::size_t k = pl.begin(i); k < pl.end(i); ++k) {
      const int j = pl.j[k];
      if (bd[j] != bd[i]) continue;
      const Vec<D> d = -pl.r(x, i, k);
      res += pw[k] * (d - F * initial_difference(X0[j], X0[i])).squaredNorm();
    }
    dis[i] = std::sqrt(res / den) / dp;
    if (store_fit && kFls_ >= 0) fls[i] = F;
  }
}

template <int D>
void SolidModule<D>::before_rebuild(Simulation<D>& sim) {
  // The reference configuration moves to the current one: F_init <- F (MMB Eq. 30).
  if (rstart_.size() != sim.particles().size() + 1) return;
  compute_deformation_gradient(sim);
  auto& p = sim.particles();
  auto F = p.template view<Mat<D>>(kF_);
  auto Fi = p.template view<Mat<D>>(kFinit_);
  auto ph = p.phase();
  auto bd = p.body();
  for (std::size_t i = 0; i < p.size(); ++i)
    if (eulerian(ph[i], bd[i]) || ph[i] != kSolid) Fi[i] = F[i];
}

template <int D>
void SolidModule<D>::on_rebuild(Simulation<D>& sim) {
  auto& p = sim.particles();
  const auto& nb = sim.neighbours();
  const auto& W = sim.kernel();
  auto x = p.x();
  auto m = p.m();
  auto rho = p.rho();
  auto ph = p.phase();
  auto bd = p.body();
  const std::size_t n = p.size();
  const double rc2 = W.radius() * W.radius();
  // Reference pairs: same solid body, within the kernel support in the reference configuration.
  rstart_.assign(n + 1, 0);
#pragma omp parallel for schedule(runtime)
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t c = 0;
    if (eulerian(ph[i], bd[i]))
      for (std::size_t k = nb.begin(i); k < nb.end(i); ++k) {
        const int j = nb.nbr(k);
        c += bd[j] == bd[i] && nb.rij(x[i], x[j], k).squaredNorm() < rc2;
      }
    rstart_[i + 1] = c;
  }
  for (std::size_t i = 0; i < n; ++i) rstart_[i + 1] += rstart_[i];
  rj_.resize(rstart_[n]);
  rcode_.resize(rstart_[n]);
  rg_.resize(rstart_[n]);
  const std::uint8_t* code = nb.code_data();
#pragma omp parallel for schedule(runtime)
  for (std::size_t i = 0; i < n; ++i) {
    if (!eulerian(ph[i], bd[i])) continue;
    std::size_t q = rstart_[i];
    Mat<D> b = Mat<D>::Zero();
    for (std::size_t k = nb.begin(i); k < nb.end(i); ++k) {
      const int j = nb.nbr(k);
      const Vec<D> r = nb.rij(x[i], x[j], k);
      const double r2 = r.squaredNorm();
      if (bd[j] != bd[i] || r2 >= rc2) continue;
      const double vf = m[j] / rho[j] * W.f(std::sqrt(r2));  // V_j at the reference time
      rj_[q] = j;
      rcode_[q] = code[k];
      rg_[q] = vf * r;  // V_j grad W(X_ij), corrected below
      b.noalias() -= vf * (r * r.transpose());
      ++q;
    }
    const Mat<D> lref = invert_correction<D>(b);  // MMB Eq. 9 in the reference configuration
    for (std::size_t k = rstart_[i]; k < rstart_[i + 1]; ++k) rg_[k] = lref * rg_[k];
  }
  if (tl_) tl_->on_rebuild(sim);  // total-Lagrangian reference pairs: built once, then re-mapped
  // A restart's rebuild restoring the last one (Simulation::restoring): F_ref, X_ref and F are
  // those of the checkpoint, which that rebuild's reset below and the steps since made.
  if (sim.restoring()) return;
  // F_ref = I now: F = F_init; the reference positions are the current ones.
  auto F = p.template view<Mat<D>>(kF_);
  auto Fi = p.template view<Mat<D>>(kFinit_);
  auto Fr = p.template view<Mat<D>>(kFref_);
  auto Xr = p.template view<Vec<D>>(kXref_);
  for (std::size_t i = 0; i < n; ++i) {
    Fr[i] = Mat<D>::Identity(), Xr[i] = x[i];
    if (eulerian(ph[i], bd[i]) || ph[i] != kSolid) F[i] = Fi[i];
  }
}

template <int D>
double SolidModule<D>::max_dt(Simulation<D>& sim) {
  // Stiffness-based hourglass springs (Eq. 32): omega_max^2 <= max_i omega2_i (Gershgorin bound
  // from the last force pass). Verlet is stable for omega dt < 2; the acoustic limit CFL h/c_L
  // sits near omega dt = 4 CFL (about 1.2 at CFL 0.3). The spring limit dt = 3 CFL/omega_max keeps
  // omega dt <= 0.9 there, so that both together stay below sqrt(1.2^2 + 0.9^2) = 1.5.
  double w2 = 0;
  if (omega2_.size() != sim.particles().size()) return std::numeric_limits<double>::infinity();
  const std::size_t n = sim.owned();
#pragma omp parallel for reduction(max : w2) schedule(runtime)
  for (std::size_t i = 0; i < n; ++i) w2 = std::max(w2, omega2_[i]);
  double dt =
      w2 > 0 ? 3.0 * sim.scene().cfl / std::sqrt(w2) : std::numeric_limits<double>::infinity();
  if (any_self_contact_ && contact_w2_.size() == sim.particles().size()) {
    double c2 = 0;  // self-contact springs: 20 steps per contact period, as the grain contact
#pragma omp parallel for reduction(max : c2) schedule(runtime)
    for (std::size_t i = 0; i < n; ++i) c2 = std::max(c2, contact_w2_[i]);
    if (c2 > 0) dt = std::min(dt, 0.1 * std::numbers::pi / std::sqrt(c2));
  }
  return dt;
}

template class SolidModule<2>;
template class SolidModule<3>;

}  // namespace monosph
