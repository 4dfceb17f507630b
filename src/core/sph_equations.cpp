#include "sph_equations.hpp"

#include <limits>

namespace monosph {

namespace {
// Fluid particles form one continuum; each solid body is its own.
inline std::int64_t group(std::int64_t phase, std::int64_t body) {
  return phase == kFluid ? -1 : body;
}
}  // namespace

template <int D>
Mat<D> invert_correction(const Mat<D>& b) {
  using M = Eigen::Matrix<double, D, D>;
  M bs = 0.5 * (M(b) + M(b).transpose());
  Eigen::SelfAdjointEigenSolver<M> es;
  es.computeDirect(bs);
  auto lam = es.eigenvalues();
  if (lam.minCoeff() >= 0.02) return Mat<D>(M(b).inverse());
  Eigen::Matrix<double, D, 1> inv;
  for (int k = 0; k < D; ++k) inv[k] = lam[k] >= 0.02 ? 1.0 / lam[k] : 1.0;
  return Mat<D>(es.eigenvectors() * inv.asDiagonal() * es.eigenvectors().transpose());
}

template <int D>
SphEquations<D>::SphEquations(Simulation<D>& sim, bool store_velocity_gradient) {
  auto& p = sim.particles();
  kshep_ = p.add_field("shepard", 1);
  kcorr_ = p.add_field("correction", D * D);
  if (store_velocity_gradient) kgradv_ = p.add_field("velocity_gradient", D * D);
}

template <int D>
void SphEquations<D>::sums(Simulation<D>& sim) {
  auto& p = sim.particles();
  const auto& nb = sim.neighbours();
  const auto& W = sim.kernel();
  auto x = p.x();
  auto m = p.m();
  auto rho = p.rho();
  auto ph = p.phase();
  auto bd = p.body();
  auto shep = p.template view<double>(kshep_);
  auto corr = p.template view<Mat<D>>(kcorr_);
  const double w0 = W.w(0.0);
  const std::size_t n = p.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const auto gi = group(ph[i], bd[i]);
    double s = m[i] / rho[i] * w0;
    Mat<D> b = Mat<D>::Zero();
    for (std::size_t k = nb.begin(i); k < nb.end(i); ++k) {
      const int j = nb.nbr(k);
      if (group(ph[j], bd[j]) != gi) continue;
      const Vec<D> r = nb.rij(x[i], x[j], k);
      const double rr = r.norm();
      const double vj = m[j] / rho[j];
      s += vj * W.w(rr);
      // (x_j - x_i) (x) grad_i W_ij = (-r) (x) (F r)   (MMB Eq. 9)
      b.noalias() -= (vj * W.f(rr)) * (r * r.transpose());
    }
    shep[i] = s;
    corr[i] = invert_correction<D>(b);
  }
}

template <int D>
void SphEquations<D>::rates(Simulation<D>& sim) {
  auto& p = sim.particles();
  const auto& nb = sim.neighbours();
  const auto& W = sim.kernel();
  auto x = p.x();
  auto v = p.v();
  auto m = p.m();
  auto rho = p.rho();
  auto drho = p.drho();
  auto ph = p.phase();
  auto bd = p.body();
  auto corr = p.template view<Mat<D>>(kcorr_);
  std::span<Mat<D>> gradv;
  if (kgradv_ >= 0) gradv = p.template view<Mat<D>>(kgradv_);
  const auto& bodies = sim.bodies();
  const auto& mats = sim.materials();
  auto mt = p.material();
  bool diffusion = false;
  for (const auto& b : bodies) diffusion = diffusion || b.delta > 0;
  const double h = sim.kernel().h();
  const std::size_t n = p.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const auto gi = group(ph[i], bd[i]);
    Mat<D> g = Mat<D>::Zero();
    double diff = 0;
    const double di = bodies[bd[i]].delta, ci = mats[mt[i]].sound_speed();
    for (std::size_t k = nb.begin(i); k < nb.end(i); ++k) {
      const int j = nb.nbr(k);
      if (group(ph[j], bd[j]) != gi) continue;
      const Vec<D> r = nb.rij(x[i], x[j], k);
      const double fr = W.f(r.norm());
      const double vj = m[j] / rho[j];
      g.noalias() += (v[j] - v[i]) * (vj * fr * r).transpose();  // sum V_j (v_j - v_i) (x) grad W
      if (diffusion) {
        // MMB Eq. 21: Psi_ij . grad W_ij = 2 delta h c (rho_j - rho_i)/rho_i (x_j - x_i).(F r)/r^2
        const double delta = 0.5 * (di + bodies[bd[j]].delta);
        const double c = 0.5 * (ci + mats[mt[j]].sound_speed());
        diff += vj * 2.0 * delta * h * c * (rho[j] - rho[i]) * (-fr);
      }
    }
    g = g * corr[i].transpose();  // corrected gradient: grad~W = L grad W (MMB Eq. 7, 16)
    drho[i] = -rho[i] * g.trace() + diff;  // MMB Eq. 11 (continuity + density diffusion)
    if (kgradv_ >= 0) gradv[i] = g;
  }
}

template <int D>
void SphEquations<D>::constitutive(Simulation<D>& sim) {
  auto& p = sim.particles();
  auto rho = p.rho();
  auto pr = p.p();
  auto mt = p.material();
  const auto& mats = sim.materials();
  const std::size_t n = p.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const Material& mm = mats[mt[i]];
    pr[i] = mm.bulk_modulus * (rho[i] / mm.density - 1.0);  // MMB Eq. 13
  }
}

template <int D>
void SphEquations<D>::forces(Simulation<D>& sim) {
  auto& p = sim.particles();
  const auto& nb = sim.neighbours();
  const auto& W = sim.kernel();
  auto x = p.x();
  auto v = p.v();
  auto a = p.a();
  auto m = p.m();
  auto rho = p.rho();
  auto pr = p.p();
  auto ph = p.phase();
  auto bd = p.body();
  auto mt = p.material();
  auto shep = p.template view<double>(kshep_);
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
  rmin_.assign(n, std::numeric_limits<double>::infinity());
  jmin_.assign(n, -1);
  // Sigma_i / (rho_i^2 S_i), the per-particle factor of the normalised stress divergence.
  sig_.resize(n);
  auto& rmin = rmin_;
  auto& jmin = jmin_;
  auto& sig = sig_;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    Mat<D> s = -pr[i] * Mat<D>::Identity();
    if (kstress_ >= 0) s += dev[i].template topLeftCorner<D, D>();  // MMB Eq. 12
    sig[i] = s / (rho[i] * rho[i] * shep[i]);
  }
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const auto gi = group(ph[i], bd[i]);
    const double ci = mats[mt[i]].sound_speed();
    const double ai = bodies[bd[i]].av_alpha, bi = bodies[bd[i]].av_beta;
    Vec<D> acc = Vec<D>::Zero();
    for (std::size_t k = nb.begin(i); k < nb.end(i); ++k) {
      const int j = nb.nbr(k);
      const Vec<D> r = nb.rij(x[i], x[j], k);
      const double rr = r.norm();
      if (rr < rmin[i]) rmin[i] = rr, jmin[i] = j;
      if (group(ph[j], bd[j]) != gi) continue;
      const Vec<D> gw = W.f(rr) * r;  // grad_i W_ij
      // MMB Eq. 11: m_j [Sigma_i/(rho_i^2 S_i) + Sigma_j/(rho_j^2 S_j)] grad_i W_ij
      Vec<D> f = (sig[i] + sig[j]) * gw;
      // MMB Eq. 11, 19-20: artificial stress eps R f_ij^n (art = eps R / (rho^2 S), same body).
      if (kas_ >= 0 && bodies[bd[i]].as_epsilon > 0)
        f -= std::pow(W.w(rr) / wdp, bodies[bd[i]].as_n) * ((art[i] + art[j]) * gw);
      // MMB Eq. 17-18: artificial viscosity, only for approaching pairs.
      const double vr = (v[i] - v[j]).dot(r);
      const double alpha = 0.5 * (ai + bodies[bd[j]].av_alpha);
      const double beta = 0.5 * (bi + bodies[bd[j]].av_beta);
      if (vr < 0 && alpha + beta > 0) {
        const double cbar = 0.5 * (ci + mats[mt[j]].sound_speed());
        const double phi = h * vr / (rr * rr + eta2);
        f += ((alpha * cbar - beta * phi) * phi / (0.5 * (rho[i] + rho[j]))) * gw;
      }
      acc += m[j] * f;
    }
    a[i] += acc;
  }
  double best = std::numeric_limits<double>::infinity();
  long imin = -1;
  for (std::size_t i = 0; i < n; ++i)
    if (rmin[i] < best) best = rmin[i], imin = static_cast<long>(i);
  if (imin >= 0) sim.set_min_distance(best, imin, jmin[imin]);
}

template class SphEquations<2>;
template class SphEquations<3>;
template Mat<2> invert_correction<2>(const Mat<2>&);
template Mat<3> invert_correction<3>(const Mat<3>&);

}  // namespace monosph
