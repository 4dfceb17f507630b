#include "core/sph_equations.hpp"

#include <cmath>
#include <limits>

namespace monosph {

template <int D>
Mat<D> invert_correction(const Mat<D>& b) {
  using M = Eigen::Matrix<double, D, D>;
  const M bs = 0.5 * (M(b) + M(b).transpose());
  // Smallest eigenvalue >= 0.02 <=> bs - 0.02 I is positive definite (Sylvester: all leading
  // principal minors positive) -- the common case, without an eigen-decomposition.
  const M c = bs - 0.02 * M::Identity();
  bool pd = c(0, 0) > 0 && c(0, 0) * c(1, 1) - c(0, 1) * c(1, 0) > 0;
  if constexpr (D == 3) pd = pd && c.determinant() > 0;
  if (pd) return Mat<D>(bs.inverse());
  Eigen::SelfAdjointEigenSolver<M> es;
  es.computeDirect(bs);
  auto lam = es.eigenvalues();
  if (lam.minCoeff() >= 0.02) return Mat<D>(bs.inverse());
  Eigen::Matrix<double, D, 1> inv;
  for (int k = 0; k < D; ++k) inv[k] = lam[k] >= 0.02 ? 1.0 / lam[k] : 1.0;
  return Mat<D>(es.eigenvectors() * inv.asDiagonal() * es.eigenvectors().transpose());
}

template <int D>
SphEquations<D>::SphEquations(Simulation<D>& sim, bool store_velocity_gradient) {
  auto& p = sim.particles();
  kshep_ = p.add_field("shepard", 1);
  kcorr_ = p.add_field("correction", D * D);
  p.set_meaning({kcorr_}, ~0u, 1.0);  // the identity on a full support: F_zz = 1 in 2D
  if (store_velocity_gradient) kgradv_ = p.add_field("velocity_gradient", D * D);
  for (const auto& b : sim.bodies()) {
    tl_.push_back(b.total_lagrangian ? 1 : 0);
    solid_.push_back(b.phase == kSolid ? 1 : 0);
    any_av_ = any_av_ || b.av_alpha > 0 || b.av_beta > 0;
    any_diffusion_ = any_diffusion_ || b.delta > 0;
  }
}

template <int D>
void SphEquations<D>::sums(Simulation<D>& sim) {
  auto& p = sim.particles();
  auto x = p.x();
  const auto& pl = sim.pairs();
  const auto& pw = pl.w;
  const auto& pf = pl.f;
  const auto& grp = sim.group();
  const auto& vol = sim.volumes();
  auto shep = p.template view<double>(kshep_);
  auto corr = p.template view<Mat<D>>(kcorr_);
  const double w0 = sim.kernel().w(0.0);
  auto ph = p.phase();
  auto bd = p.body();
  const std::size_t n = p.size();
#pragma omp parallel for schedule(runtime)
  for (std::size_t i = 0; i < n; ++i) {
    if ((solids_only_ && ph[i] != kSolid) || skip(bd[i])) continue;
    const int gi = grp[i];
    const auto row = pl.row(x, i);
    double s = vol[i] * w0;
    Mat<D> b = Mat<D>::Zero();
    for (std::size_t k = pl.begin(i); k < pl.end(i); ++k) {
      const int j = pl.j[k];
      if (grp[j] != gi) continue;
      const Vec<D> r = row.r(k);
      s += vol[j] * pw[k];
      // (x_j - x_i) (x) grad_i W_ij = (-r) (x) (F r)   (MMB Eq. 9)
      b.noalias() -= (vol[j] * pf[k]) * (r * r.transpose());
    }
    shep[i] = s;  // Shepard sum, denominator of the normalised gradient (MMB Eq. 10)
    corr[i] = invert_correction<D>(b);
  }
  sim.exchange({kshep_, kcorr_});  // the stress factor of neighbours uses both
}

template <int D>
void SphEquations<D>::rates(Simulation<D>& sim) {
  auto& p = sim.particles();
  auto x = p.x();
  const auto& pl = sim.pairs();
  const auto& pf = pl.f;
  const auto& grp = sim.group();
  const auto& vol = sim.volumes();
  auto v = p.v();
  auto rho = p.rho();
  auto drho = p.drho();
  auto corr = p.template view<Mat<D>>(kcorr_);
  std::span<Mat<D>> gradv;
  if (kgradv_ >= 0) gradv = p.template view<Mat<D>>(kgradv_);
  const auto& bodies = sim.bodies();
  const auto& mats = sim.materials();
  auto mt = p.material();
  auto bd = p.body();
  auto ph = p.phase();
  const double h = sim.kernel().h();
  const std::size_t n = p.size();
  if (any_diffusion_) {
    cs_.resize(n);
    delta_.resize(n);
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i)
      cs_[i] = mats[mt[i]].sound_speed(), delta_[i] = bodies[bd[i]].delta;
  }
#pragma omp parallel for schedule(runtime)
  for (std::size_t i = 0; i < n; ++i) {
    if ((solids_only_ && ph[i] != kSolid) || skip(bd[i])) continue;
    const int gi = grp[i];
    const auto row = pl.row(x, i);
    Mat<D> g = Mat<D>::Zero();
    double diff = 0;
    for (std::size_t k = pl.begin(i); k < pl.end(i); ++k) {
      const int j = pl.j[k];
      if (grp[j] != gi) continue;
      const Vec<D> r = row.r(k);
      const double vj = vol[j];
      g.noalias() +=
          (v[j] - v[i]) * (vj * pf[k] * r).transpose();  // sum V_j (v_j - v_i) (x) grad W
      if (any_diffusion_) {
        // MMB Eq. 21: Psi_ij . grad W_ij = 2 delta h c (rho_j - rho_i)/rho_i (x_j - x_i).(F r)/r^2
        const double delta = 0.5 * (delta_[i] + delta_[j]);
        const double c = 0.5 * (cs_[i] + cs_[j]);
        diff -= vj * 2.0 * delta * h * c * (rho[j] - rho[i]) * pf[k];
      }
    }
    g = g * corr[i].transpose();           // corrected gradient: grad~W = L grad W (MMB Eq. 7, 16)
    drho[i] = -rho[i] * g.trace() + diff;  // MMB Eq. 11 (continuity + density diffusion)
    if (kgradv_ >= 0) gradv[i] = g;
  }
  // Ghosts integrate density and stress (from grad v) as their owners do.
  if (kgradv_ >= 0)
    sim.exchange({p.find("density_rate"), kgradv_});
  else
    sim.exchange({p.find("density_rate")});
}

template <int D>
void SphEquations<D>::constitutive(Simulation<D>& sim) {
  auto& p = sim.particles();
  auto rho = p.rho();
  auto pr = p.p();
  auto mt = p.material();
  auto ph = p.phase();
  auto bd = p.body();
  const auto& mats = sim.materials();
  const std::size_t n = p.size();
#pragma omp parallel for schedule(runtime)
  for (std::size_t i = 0; i < n; ++i) {
    if ((solids_only_ && ph[i] != kSolid) || skip(bd[i])) continue;
    const Material& mm = mats[mt[i]];
    pr[i] = mm.pressure(rho[i]);  // MMB Eq. 13
  }
}

template <int D>
void SphEquations<D>::forces(Simulation<D>& sim) {
  auto& p = sim.particles();
  auto x = p.x();
  const auto& pl = sim.pairs();
  const auto& W = sim.kernel();
  const auto& pw = pl.w;
  const auto& pf = pl.f;
  const auto& grp = sim.group();
  const auto& vol = sim.volumes();
  auto v = p.v();
  auto a = p.a();
  auto m = p.m();
  auto rho = p.rho();
  auto pr = p.p();
  auto bd = p.body();
  auto mt = p.material();
  auto shep = p.template view<double>(kshep_);
  auto corr = p.template view<Mat<D>>(kcorr_);
  auto ph = p.phase();
  if (kstress_ < 0) kstress_ = p.find("deviatoric_stress");
  std::span<Mat3> dev;
  if (kstress_ >= 0) dev = p.template view<Mat3>(kstress_);
  if (kas_ < 0) kas_ = p.find("artificial_stress");
  std::span<Mat<D>> art;
  if (kas_ >= 0) art = p.template view<Mat<D>>(kas_);
  const double wdp = W.w(sim.dp());
  const auto& mats = sim.materials();
  const auto& bodies = sim.bodies();
  const double h = W.h(), eta2 = 0.01 * h * h;
  const std::size_t n = p.size();
  sig_.resize(n);
  wpair_.resize(n);
  if (any_av_) {
    cs_.resize(n);
    alpha_.resize(n);
    beta_.resize(n);
    phimax_.resize(n);  // each row of the force loop sets its own
  }
  // Per-particle factor T_i of the stress divergence a_i = c_i sum_j w_j (T_i + T_j) grad_i W_ij:
  // normalised (MMB Eq. 10-11): T = Sigma/(rho^2 S), w_j = m_j, c_i = 1;
  // corrected (Bonet & Lok 1999): T = Sigma L, w_j = V_j, c_i = 1/rho_i -- the exact adjoint of the
  // corrected velocity gradient (Eq. 16), so that sum_i m_i a_i.v_i = -sum_i V_i Sigma_i : grad
  // v_i.
#pragma omp parallel for schedule(runtime)
  for (std::size_t i = 0; i < n; ++i) {
    Mat<D> s = -pr[i] * Mat<D>::Identity();
    // MMB Eq. 12; the non-hourglass formulation (Zhang et al. 2024) takes the shear force from
    // a Laplacian (solid module) and only the pressure from here (its Eq. 9 and 12).
    if (kstress_ >= 0 && bodies[bd[i]].formulation != 2) s += dev[i].template topLeftCorner<D, D>();
    if (bodies[bd[i]].corrected_divergence) {
      sig_[i] = s * corr[i];
      wpair_[i] = vol[i];
    } else {
      sig_[i] = s / (rho[i] * rho[i] * shep[i]);
      wpair_[i] = m[i];
    }
    if (any_av_) {
      // Particles these equations skip do not limit the step (cs = 0: h/0 = inf).
      cs_[i] = solids_only_ && ph[i] != kSolid ? 0.0 : mats[mt[i]].sound_speed();
      alpha_[i] = bodies[bd[i]].av_alpha;
      beta_[i] = bodies[bd[i]].av_beta;
    }
  }
#pragma omp parallel for schedule(runtime)
  for (std::size_t i = 0; i < n; ++i) {
    if ((solids_only_ && ph[i] != kSolid) || skip(bd[i])) {
      if (any_av_) phimax_[i] = 0.0;
      continue;
    }
    const int gi = grp[i];
    const auto row = pl.row(x, i);
    const double as_eps = bodies[bd[i]].as_epsilon, as_n = bodies[bd[i]].as_n;
    Vec<D> acc = Vec<D>::Zero(), accs = Vec<D>::Zero();
    double phim = 0.0;  // largest -phi_ij of the approaching pairs, for max_dt
    for (std::size_t k = pl.begin(i); k < pl.end(i); ++k) {
      const int j = pl.j[k];
      if (grp[j] != gi) continue;
      const Vec<D> r = row.r(k);
      const Vec<D> gw = pf[k] * r;  // grad_i W_ij
      // MMB Eq. 11: m_j [Sigma_i/(rho_i^2 S_i) + Sigma_j/(rho_j^2 S_j)] grad_i W_ij (or corrected)
      accs.noalias() += wpair_[j] * ((sig_[i] + sig_[j]) * gw);
      if (!any_av_ && !(kas_ >= 0 && as_eps > 0)) continue;
      Vec<D> f = Vec<D>::Zero();
      // MMB Eq. 11, 19-20: artificial stress eps R f_ij^n (art = eps R / (rho^2 S), same body).
      if (kas_ >= 0 && as_eps > 0) {
        const double q = pw[k] / wdp, q2 = q * q;  // (W/W(dp))^n; n = 4 without pow
        f -= (as_n == 4 ? q2 * q2 : std::pow(q, as_n)) * ((art[i] + art[j]) * gw);
      }
      if (any_av_) {  // MMB Eq. 17-18: artificial viscosity, only for approaching pairs
        const double vr = (v[i] - v[j]).dot(r);
        if (vr < 0) {
          const double alpha = 0.5 * (alpha_[i] + alpha_[j]), beta = 0.5 * (beta_[i] + beta_[j]);
          const double cbar = 0.5 * (cs_[i] + cs_[j]);
          const double phi = h * vr / (r.squaredNorm() + eta2);
          f += ((alpha * cbar - beta * phi) * phi / (0.5 * (rho[i] + rho[j]))) * gw;
          phim = std::max(phim, -phi);
        }
      }
      acc += m[j] * f;
    }
    if (any_av_) phimax_[i] = phim;
    a[i] += acc + (bodies[bd[i]].corrected_divergence ? accs / rho[i] : accs);
  }
}

template <int D>
double SphEquations<D>::max_dt(Simulation<D>& sim) {
  // Viscous criterion of the artificial viscosity (Monaghan 1992):
  // dt <= CFL h / (c + 0.6 (alpha c + beta max_j |phi_ij|)).
  if (!any_av_ || phimax_.size() != sim.particles().size())
    return std::numeric_limits<double>::infinity();
  const double h = sim.kernel().h();
  double dt = std::numeric_limits<double>::infinity();
  const std::size_t n = sim.owned();
#pragma omp parallel for reduction(min : dt) schedule(runtime)
  for (std::size_t i = 0; i < n; ++i)
    dt = std::min(dt, h / (cs_[i] + 0.6 * (alpha_[i] * cs_[i] + beta_[i] * phimax_[i])));
  return sim.scene().cfl * dt;
}

template class SphEquations<2>;
template class SphEquations<3>;
template Mat<2> invert_correction<2>(const Mat<2>&);
template Mat<3> invert_correction<3>(const Mat<3>&);

}  // namespace monosph
