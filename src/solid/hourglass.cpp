// Hourglass control of the Eulerian solid (Mohseni-Mofidi & Bierwisch 2020, Eq. 31-34), part of
// SolidModule::forces, with the shear Laplacian of the non-hourglass formulation.
#include <algorithm>
#include <cmath>

#include "solid_module.hpp"

namespace monosph {

namespace {

// What the pair loop of one particle reads: the fields, and the particle's own constants.
template <int D>
struct HourglassRow {
  typename PairList<D>::Row row;
  const PairList<D>* pl;
  const Vec<D>*x, *v, *X0, *Xr;
  const Mat<D>* F;
  const double *m, *rho, *vol, *ep, *sy;
  const std::int64_t* bd;
  int ref;     // 0 initial, 1 intermediate, 2 least squares (F holds the choice)
  bool wrap;   // periodic axes: the initial difference is the minimum image
  Vec<D> box;  // periodic length of each axis, 0 along the others
  bool sw;     // Ganzenmueller's plastic switch
  double E, Ei, kstiff, kvisc, eta2;
};

struct HourglassSums {
  double kappa = 0;   // sum_j V_j W_ij E_ij / X_ij^2: the pair spring stiffnesses / (V_i xi)
  double stored = 0;  // sum_j V_j W_ij E_ij (eps . x_ij)^2 / (X_ij^2 r_ij^2)
};

// The pairs of particle i. Every pair force is along x_ij, so one scalar per pair is summed.
// Visc: the viscous part (Eq. 33) is on; it is evaluated for every pair and masked, not branched
// on (whether the relative motion increases the error changes from pair to pair at random).
// Ref: how X_ij is formed (0 initial, 1 intermediate, 2 initial with periodic minimum image);
// Sw: Ganzenmueller's plastic switch. Compile-time, so that the loop holds only what it uses;
// flatten: the twelve copies would otherwise exceed GCC's inlining budget of the file and call
// the Eigen expressions out of line (measured: the forces pass 1.7x slower).
template <int D, bool Visc, int Ref, bool Sw>
[[gnu::flatten]] Vec<D> hourglass_pairs(const HourglassRow<D>& h, std::size_t i,
                                        HourglassSums& out) {
  const PairList<D>& pl = *h.pl;
  const int* __restrict pj = pl.j.data();
  const double* __restrict pw = pl.w.data();
  const double* __restrict pf = pl.f.data();
  const Vec<D>* __restrict x = h.x;
  const Vec<D>* __restrict X0 = Ref == 1 ? h.Xr : h.X0;
  const Mat<D>* __restrict F = h.F;
  const double* __restrict vol = h.vol;
  const std::int64_t* __restrict bd = h.bd;
  const Mat<D> Fi = F[i];
  const Vec<D> xi = x[i], vi = h.v[i], Xi = X0[i];
  const std::int64_t bi = bd[i];
  const double rhoi = h.rho[i], E = h.E, Ei = h.Ei, eta2 = h.eta2;
  const double kvisc2 = 2 * h.kvisc;
  const Vec<D> box = h.box;
  Vec<D> f = Vec<D>::Zero();
  double kappa = 0, stored = 0;
  for (std::size_t k = pl.begin(i); k < pl.end(i); ++k) {
    const int j = pj[k];
    if (bd[j] != bi) continue;
    const Vec<D> d = -h.row.r(k);  // x_ij = x_j - x_i (Ganzenmueller's convention)
    Vec<D> X;
    if constexpr (Ref == 1)
      X = X0[j] + (xi - x[j] + d) - Xi;  // + the image shift
    else if constexpr (Ref == 2)
      X = minimum_image<D>(X0[j] - Xi, box);  // the box held in registers
    else
      X = X0[j] - Xi;
    const double X2 = X.squaredNorm();
    const Vec<D> eps = 0.5 * (Fi + Mat<D>(F[j])) * X - d;  // MMB Eq. 31
    const double r2 = d.squaredNorm();
    const double ed = eps.dot(d);  // (eps . x_ij), |x_ij| times the projection
    // Pair modulus: symmetric so that the pair forces stay equal and opposite.
    double Eij = E;
    if constexpr (Sw) Eij = 0.5 * (Ei + (h.ep[j] > 0 ? h.sy[j] : E));
    const double kw = vol[j] * pw[k] * Eij;
    double inv, s;
    if constexpr (Visc) {
      // One division for 1/(X^2 r^2) and 1/(X^2 rbar (r^2 + eta^2)), rbar = (rho_i + rho_j)/2;
      // |eps|/|X| = sqrt(|eps|^2 X^2)/X^2, so the root does not wait for the division.
      const double rr = (rhoi + h.rho[j]) * (r2 + eta2);
      const double q = 1.0 / (X2 * r2 * rr);
      inv = q * rr;
      // MMB Eq. 33: viscous force, only when the relative motion increases the error.
      const double vr = (h.v[j] - vi).dot(d);
      const double on = vr * ed < 0 ? 1.0 : 0.0;
      s = on * (kvisc2 * h.m[j] * vr * pf[k]) * std::sqrt(eps.squaredNorm() * X2) * (q * r2);
    } else {
      inv = 1.0 / (X2 * r2);
      s = 0;
    }
    kappa += kw * r2 * inv;  // k_ij = kw / X2
    stored += kw * ed * ed * inv;
    s += h.kstiff * kw * ed * inv;  // MMB Eq. 32: stiffness part along the current pair direction
    f += s * d;
  }
  out.kappa = kappa;
  out.stored = stored;
  return f;
}

template <int D, bool Visc, int Ref>
Vec<D> hourglass_pairs(const HourglassRow<D>& h, std::size_t i, HourglassSums& out) {
  return h.sw ? hourglass_pairs<D, Visc, Ref, true>(h, i, out)
              : hourglass_pairs<D, Visc, Ref, false>(h, i, out);
}

template <int D, bool Visc>
Vec<D> hourglass_pairs(const HourglassRow<D>& h, std::size_t i, HourglassSums& out) {
  if (h.ref == 1) return hourglass_pairs<D, Visc, 1>(h, i, out);
  return h.wrap ? hourglass_pairs<D, Visc, 2>(h, i, out) : hourglass_pairs<D, Visc, 0>(h, i, out);
}

}  // namespace

template <int D>
void SolidModule<D>::forces(Simulation<D>& sim) {
  auto& p = sim.particles();
  const auto& pl = sim.pairs();
  auto x = p.x();
  auto a = p.a();
  auto m = p.m();
  auto rho = p.rho();
  auto ph = p.phase();
  auto bd = p.body();
  auto mt = p.material();
  auto Ftot = p.template view<Mat<D>>(kF_);
  auto Fref = p.template view<Mat<D>>(kFref_);
  std::span<Mat<D>> Fls;
  if (kFls_ >= 0) Fls = p.template view<Mat<D>>(kFls_);
  const auto& bodies = sim.bodies();
  const auto& mats = sim.materials();
  const double h = sim.kernel().h();
  const std::size_t n = p.size();
  const bool wrap = (period_.array() > 0).any();
  const auto& vol = sim.volumes();
  std::span<double> ep, sy;
  if (ksy_ >= 0) ep = p.template view<double>(kep_), sy = p.template view<double>(ksy_);
  omega2_.resize(n);  // every row set below (TL rows again by tl_->forces)
  std::span<double> hge;
  if (khge_ >= 0) hge = p.template view<double>(khge_);
  std::span<Vec<D>> lap;
  if (klap_ >= 0) lap = p.template view<Vec<D>>(klap_);
  HourglassRow<D> base{};
  base.pl = &pl;
  base.x = x.data(), base.v = p.v().data(), base.m = m.data(), base.rho = rho.data();
  base.vol = vol.data(), base.bd = bd.data(), base.ep = ep.data(), base.sy = sy.data();
  base.X0 = p.template view<Vec<D>>(kX0_).data();
  base.Xr = p.template view<Vec<D>>(kXref_).data();
  base.wrap = wrap, base.eta2 = 0.01 * h * h, base.box = period_;
#pragma omp parallel for schedule(runtime)
  for (std::size_t i = 0; i < n; ++i) {
    omega2_[i] = 0.0;
    if (!eulerian(ph[i], bd[i])) continue;
    const BodyInfo& b = bodies[bd[i]];
    const SolidBodyKeys& sk = keys_[bd[i]];
    const Material& mat = mats[mt[i]];
    // Zhang et al. 2024, Eq. 20: shear acceleration 2 zeta G / rho_i I_i (no stress divergence).
    if (b.formulation == 2) a[i] += (2 * sk.laplacian_zeta * mat.shear_modulus / rho[i]) * lap[i];
    if (!(sk.hg_xi > 0 || (sk.hg_zeta > 0 && sk.hg_chi > 0))) continue;
    HourglassRow<D> hr = base;
    hr.row = pl.row(x, i);
    hr.E = 9 * mat.bulk_modulus * mat.shear_modulus / (3 * mat.bulk_modulus + mat.shear_modulus);
    // Ganzenmueller's switch: a plastically deformed particle uses its yield stress for E.
    hr.sw = sk.hg_plastic_switch && ksy_ >= 0;
    hr.Ei = hr.sw && ep[i] > 0 ? sy[i] : hr.E;
    hr.kstiff = -sk.hg_xi * (1 - sk.hg_chi) * vol[i];
    hr.kvisc = -sk.hg_zeta * sk.hg_chi * m[i] * mat.sound_speed() * h;
    // MMB Eq. 31 literally: total F and the initial configuration; or F_ref and the
    // configuration of the last neighbour rebuild (`intermediate`); or the least-squares fit of
    // the initial onto the current neighbourhood (`least_squares`).
    hr.ref = sk.hg_reference;
    hr.F = (sk.hg_reference == 0 ? Ftot : sk.hg_reference == 1 ? Fref : Fls).data();
    HourglassSums sums;
    const Vec<D> f = hr.kvisc != 0 ? hourglass_pairs<D, true>(hr, i, sums)
                                   : hourglass_pairs<D, false>(hr, i, sums);
    a[i] += f / m[i];
    // The force is -dU/dx_i of U = sum over pairs 1/2 k_ij (eps . x_ij / r_ij)^2 with
    // k_ij = xi V_i V_j W_ij E / X_ij^2; particle i holds half of each of its pairs.
    if (!hge.empty()) hge[i] = 0.25 * sk.hg_xi * (1 - sk.hg_chi) * vol[i] * sums.stored;
    // Springs k_ij = xi V_i V_j W_ij E / X_ij^2 on particle i: by Gershgorin the hourglass part of
    // the stiffness matrix has no frequency above omega^2 = 2 sum_j k_ij / m_i.
    omega2_[i] = 2.0 * sk.hg_xi * (1 - sk.hg_chi) * sums.kappa / rho[i];
  }
  if (tl_) tl_->forces(sim, omega2_, hge);  // G15 Eq. 24 and 32
  if (any_self_contact_) self_contact(sim);
}

template void SolidModule<2>::forces(Simulation<2>&);
template void SolidModule<3>::forces(Simulation<3>&);

}  // namespace monosph
