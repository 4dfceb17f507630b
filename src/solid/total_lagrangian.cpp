#include "total_lagrangian.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>

#include "core/sph_equations.hpp"

namespace monosph {

template <int D>
TotalLagrangian<D>::TotalLagrangian(Simulation<D>& sim, int kS, int kF, int kgradv, int kX0,
                                    int kep, int ksy)
    : kS_(kS), kF_(kF), kgradv_(kgradv), kX0_(kX0), kep_(kep), ksy_(ksy) {
  for (const auto& b : sim.bodies()) {
    tlb_.push_back(b.total_lagrangian ? 1 : 0);
    keys_.push_back(module_params<SolidBodyKeys>(b.params));
  }
  for (const auto& m : sim.materials())
    neo_hookean_.push_back(module_params<SolidMaterial>(m.params).neo_hookean);
  // Not decomposed over ranks: the reference pairs would cross rank boundaries.
  if (sim.comm().size() > 1) throw InputError("formulation: total_lagrangian runs on one rank");
  const Scene& sc = sim.scene();
  for (int a = 0; a < D; ++a) {
    const bool lo = sc.has_mirror() && sc.mirror_min[a], hi = sc.has_mirror() && sc.mirror_max[a];
    plane_[a] = lo ? sc.domain_min[a] : hi ? sc.domain_max[a] : std::nan("");  // one (scene check)
  }
  // Reference volume V0_j of G15 Eq. 14-24 (checkpointed: restarts rebuild the reference pairs).
  kV0_ = sim.particles().add_field("reference_volume", 1);
}

template <int D>
void TotalLagrangian<D>::on_create(Simulation<D>& sim) {
  auto& p = sim.particles();
  auto v0 = p.template view<double>(kV0_);
  auto m = p.m();
  auto rho = p.rho();
  for (std::size_t i = 0; i < p.size(); ++i) v0[i] = m[i] / rho[i];
}

template <int D>
std::size_t TotalLagrangian<D>::reference_neighbours(std::size_t i) const {
  if (i >= slot_of_.size() || slot_of_[i] < 0) return 0;
  const int s = slot_of_[i];
  return start_[s + 1] - start_[s];
}

template <int D>
void TotalLagrangian<D>::build(Simulation<D>& sim) {
  auto& p = sim.particles();
  auto bd = p.body();
  auto id = p.id();
  auto X0 = p.template view<Vec<D>>(kX0_);
  auto V0 = p.template view<double>(kV0_);
  const auto& W = sim.kernel();
  const double rc = W.radius();
  const std::size_t n = sim.owned();  // not the Mirror's images
  // Slots: the total-Lagrangian particles in id order (independent of the particle order).
  std::vector<std::size_t> ix;
  for (std::size_t i = 0; i < n; ++i)
    if (is_tl(bd[i])) ix.push_back(i);
  std::sort(ix.begin(), ix.end(), [&](std::size_t a, std::size_t b) { return id[a] < id[b]; });
  const std::size_t ns = ix.size();
  sid_.resize(ns);
  v0_.resize(ns);
  F_.assign(ns, Mat<D>::Identity());
  P_.assign(ns, Mat<D>::Zero());
  std::vector<Vec<D>> X(ns);
  std::vector<std::int64_t> body(ns);
  for (std::size_t s = 0; s < ns; ++s)
    sid_[s] = id[ix[s]], v0_[s] = V0[ix[s]], X[s] = X0[ix[s]], body[s] = bd[ix[s]];
  // Candidate neighbours: the slots (mask 0) and, for every set of symmetry planes a slot lies
  // within rc of, its image across them (mask: the planes' axes).
  std::vector<int> cslot;
  std::vector<unsigned char> cmask;
  std::vector<Vec<D>> cX;
  for (std::size_t s = 0; s < ns; ++s)
    for (unsigned m = 0; m < (1u << D); ++m) {
      bool near = true;
      for (int a = 0; a < D; ++a)
        if (m >> a & 1u) near = near && std::abs(X[s][a] - plane_[a]) < rc;  // NaN: false
      if (near) cslot.push_back(int(s)), cmask.push_back(m), cX.push_back(image(X[s], m, true));
    }
  const std::size_t nc_all = cslot.size();
  // Cells of size rc over the candidates' reference positions.
  Vec<D> lo = Vec<D>::Constant(std::numeric_limits<double>::infinity());
  for (const auto& x : cX) lo = lo.cwiseMin(x);
  std::array<std::int64_t, 3> nc{1, 1, 1};
  std::vector<std::array<std::int64_t, 3>> cell(nc_all);
  for (std::size_t c = 0; c < nc_all; ++c) {
    cell[c] = {0, 0, 0};
    for (int a = 0; a < D; ++a) {
      cell[c][a] = static_cast<std::int64_t>(std::floor((cX[c][a] - lo[a]) / rc));
      nc[a] = std::max(nc[a], cell[c][a] + 1);
    }
  }
  auto key = [&](std::int64_t cx, std::int64_t cy, std::int64_t cz) {
    return (cz * nc[1] + cy) * nc[0] + cx;
  };
  std::unordered_map<std::int64_t, std::vector<int>> grid;
  std::vector<int> first(ns);  // the candidate of each slot itself
  for (std::size_t c = 0; c < nc_all; ++c) {
    grid[key(cell[c][0], cell[c][1], cell[c][2])].push_back(static_cast<int>(c));
    if (cmask[c] == 0) first[cslot[c]] = static_cast<int>(c);
  }
  // Reference neighbours: same body, |X_ij| < rc, in slot (= id) order: the sums below run in
  // the same order whatever the particle order, so a restart reproduces them bit for bit.
  // Lists of candidates, sorted by (slot, mask) = candidate order.
  std::vector<std::vector<int>> nbr(ns);
  const int dz = D == 3 ? 1 : 0;
#pragma omp parallel for schedule(dynamic, 256)
  for (std::size_t s = 0; s < ns; ++s) {
    auto& list = nbr[s];
    const auto& cs = cell[first[s]];
    for (int cz = -dz; cz <= dz; ++cz)
      for (int cy = -1; cy <= 1; ++cy)
        for (int cx = -1; cx <= 1; ++cx) {
          const std::int64_t x = cs[0] + cx, y = cs[1] + cy, z = cs[2] + cz;
          if (x < 0 || y < 0 || z < 0 || x >= nc[0] || y >= nc[1] || z >= nc[2]) continue;
          auto it = grid.find(key(x, y, z));
          if (it == grid.end()) continue;
          for (int c : it->second)
            if (c != first[s] && body[cslot[c]] == body[s] && (cX[c] - X[s]).norm() < rc)
              list.push_back(c);
        }
    std::sort(list.begin(), list.end());
  }
  start_.assign(ns + 1, 0);
  for (std::size_t s = 0; s < ns; ++s) start_[s + 1] = start_[s] + nbr[s].size();
  const std::size_t np = start_[ns];
  nj_.resize(np);
  gr_.resize(np);
  mask_.resize(np);
  X_.resize(np);
  g_.resize(np);
  w_.resize(np);
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < ns; ++s) {
    Mat<D> b = Mat<D>::Zero();
    for (std::size_t q = 0; q < nbr[s].size(); ++q) {
      const std::size_t k = start_[s] + q;
      const int c = nbr[s][q], t = cslot[c];
      const Vec<D> r = X[s] - cX[c];  // X_i - X_j: grad_i W(X_ij) = f(|r|) r
      const double rr = r.norm(), f = W.f(rr);
      nj_[k] = t;
      mask_[k] = cmask[c];
      X_[k] = -r;                         // X_ij = X_j - X_i (G15 Fig. 1)
      w_[k] = W.w(rr) / r.squaredNorm();  // W(X_ij) / X_ij^2 of the hourglass force (G15 Eq. 32)
      g_[k] = v0_[t] * f * r;
      b.noalias() -= (v0_[t] * f) * (r * r.transpose());
    }
    // Reference correction L_i (G15 Eq. 14-16): sum_j (X_j - X_i) (x) g_ij = I.
    const Mat<D> L = invert_correction<D>(b);
    for (std::size_t k = start_[s]; k < start_[s + 1]; ++k) g_[k] = L * g_[k];
  }
  // Reverse pair (j, i) of every pair (i, j): the reference support is symmetric. For an image
  // j' = R j, the reverse is (j, R i) in j's list: g_j'i = R g_j(Ri), P_j' = R P_j R.
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < ns; ++s)
    for (std::size_t k = start_[s]; k < start_[s + 1]; ++k) {
      const int t = nj_[k];
      // t's list is sorted by (slot, mask): the candidate order.
      const auto want = std::make_pair(static_cast<int>(s), mask_[k]);
      std::size_t lo = start_[t], hi = start_[t + 1];
      while (lo < hi) {
        const std::size_t mid = (lo + hi) / 2;
        if (std::make_pair(nj_[mid], mask_[mid]) < want)
          lo = mid + 1;
        else
          hi = mid;
      }
      gr_[k] = g_[lo];  // g_ji beside g_ij: the force loop streams it instead of a gather
    }
  built_ = true;
}

template <int D>
void TotalLagrangian<D>::map_slots(Simulation<D>& sim) {
  auto& p = sim.particles();
  auto id = p.id();
  const std::size_t n = p.size();
  std::int64_t maxid = 0;
  for (std::size_t i = 0; i < n; ++i) maxid = std::max(maxid, id[i]);
  for (auto s : sid_) maxid = std::max(maxid, s);
  auto& pos = pos_;  // id -> index (kept: no allocation per rebuild)
  pos.assign(static_cast<std::size_t>(maxid) + 1, -1);
  for (std::size_t i = 0; i < sim.owned(); ++i) pos[id[i]] = static_cast<int>(i);  // no images
  idx_.resize(sid_.size());
  slot_of_.assign(n, -1);
  for (std::size_t s = 0; s < sid_.size(); ++s) {
    idx_[s] = pos[sid_[s]];
    if (idx_[s] < 0)
      throw RunAborted("total-Lagrangian particle id " + std::to_string(sid_[s]) +
                       " was removed: its reference neighbours need it");
    slot_of_[idx_[s]] = static_cast<int>(s);
  }
}

template <int D>
void TotalLagrangian<D>::on_rebuild(Simulation<D>& sim) {
  if (!built_) build(sim);  // first build, fresh or restarted (from X0 and V0)
  map_slots(sim);
}

template <int D>
void TotalLagrangian<D>::restarted(Simulation<D>& sim) {
  // F at the restart's positions (G15 Eq. 17), for the first rates: the checkpoint's, not those
  // of the rebuild the restart restores (a fresh start computes F in its first sums).
  auto x = sim.particles().x();
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < sid_.size(); ++s) F_[s] = reference_gradient(s, x, true);
}

template <int D>
void TotalLagrangian<D>::rates(Simulation<D>& sim) {
  auto& p = sim.particles();
  auto v = p.v();
  auto drho = p.drho();
  auto L = p.template view<Mat<D>>(kgradv_);
  const std::size_t ns = sid_.size();
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < ns; ++s) {
    const int i = idx_[s];
    // F of the last sums (G15 Eq. 17): the positions have not moved since (restarted() after a
    // restart), and the same loop gives the same bits.
    const Mat<D> Fd = reference_gradient(s, v, false);  // its rate
    L[i] = Fd * F_[s].inverse();                        // velocity gradient dv/dx = Fdot F^-1
    drho[i] = 0;  // rho = rho0 / det F: no continuity equation
  }
}

template <int D>
void TotalLagrangian<D>::sums(Simulation<D>& sim) {
  auto& p = sim.particles();
  auto x = p.x();
  auto m = p.m();
  auto rho = p.rho();
  auto Ff = p.template view<Mat<D>>(kF_);
  const std::size_t ns = sid_.size();
  long bad = -1;
#pragma omp parallel for schedule(static) reduction(max : bad)
  for (std::size_t s = 0; s < ns; ++s) {
    const int i = idx_[s];
    const Mat<D> F = reference_gradient(s, x, true);  // G15 Eq. 17
    F_[s] = F;
    Ff[i] = F;
    const double J = F.determinant();
    if (!(J > 0)) bad = std::max(bad, long(i));
    rho[i] = m[i] / (v0_[s] * J);  // rho0 V0 = m = rho V, V = J V0
  }
  if (bad >= 0)
    throw RunAborted("total-Lagrangian " + sim.describe(bad) +
                     ": det F <= 0 (inverted neighbourhood) at t = " + std::to_string(sim.time()));
}

template <int D>
void TotalLagrangian<D>::constitutive(Simulation<D>& sim) {
  auto& p = sim.particles();
  auto rho = p.rho();
  auto pr = p.p();
  auto mt = p.material();
  auto S = p.template view<Mat3>(kS_);
  const int kd = p.find("damage");
  std::span<double> dmg;
  if (kd >= 0) dmg = p.template view<double>(kd);
  auto bd = p.body();
  std::span<double> ep, sy;
  if (ksy_ >= 0) ep = p.template view<double>(kep_), sy = p.template view<double>(ksy_);
  const auto& mats = sim.materials();
  const std::size_t ns = sid_.size();
  E_.resize(ns);
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < ns; ++s) {
    const int i = idx_[s];
    const Material& mat = mats[mt[i]];
    // Stiffness of the hourglass force (G15 Eq. 32): with the plastic switch (G15 Sect. 4.5) a
    // plastically deformed particle uses its yield stress.
    const bool sw = keys_[bd[i]].hg_plastic_switch && ksy_ >= 0;
    E_[s] = sw && ep[i] > 0 ? sy[i] : mat.youngs_modulus();
    const Mat<D>& F = F_[s];
    const double J = F.determinant();
    if (neo_hookean_[mt[i]]) {
      // G15 Eq. 44: S = mu (I - C^-1) + lambda ln J C^-1, P = F S (G15 Eq. 20). Plane strain in
      // 2D (F_zz = 1). Cauchy sigma = P F^T / J is kept as pressure and deviator for output.
      const double mu = mat.shear_modulus, lam = mat.bulk_modulus - 2.0 * mu / 3.0;
      const Mat<D> Ci = (F.transpose() * F).inverse();
      const double lnJ = std::log(J);
      const Mat<D> S2 = mu * (Mat<D>::Identity() - Ci) + lam * lnJ * Ci;
      P_[s] = F * S2;
      Mat3 sig = Mat3::Zero();
      sig.template topLeftCorner<D, D>() = P_[s] * F.transpose() / J;
      if constexpr (D == 2) sig(2, 2) = lam * lnJ / J;
      const double pp = -sig.trace() / 3.0;
      pr[i] = pp;
      S[i] = sig + pp * Mat3::Identity();
    } else {
      // Hypoelastic: Cauchy sigma = -p I + S, p from the linear EOS (MMB Eq. 13) at rho0/det F,
      // S from the Jaumann update (and return mapping) of SolidModule::drift.
      double pp = mat.pressure(rho[i]);
      if (kd >= 0 && dmg[i] >= 1 && pp < 0) pp = 0;  // failed: no tension (as the Eulerian solid)
      pr[i] = pp;
      const Mat<D> sig = Mat<D>(S[i].template topLeftCorner<D, D>()) - pp * Mat<D>::Identity();
      P_[s] = J * sig * F.inverse().transpose();  // PK1 P = J sigma F^-T
    }
    P_[s] *= v0_[s];  // V0 P: the force pass's factor
  }
}

template <int D>
void TotalLagrangian<D>::forces(Simulation<D>& sim, std::vector<double>& omega2,
                                std::span<double> hge) {
  auto& p = sim.particles();
  auto x = p.x();
  auto a = p.a();
  auto m = p.m();
  auto bd = p.body();
  const std::size_t ns = sid_.size();
#pragma omp parallel for schedule(static)
  for (std::size_t s = 0; s < ns; ++s) {
    const int i = idx_[s];
    const double alpha = keys_[bd[i]].hg_xi;  // G15 alpha = MMB xi (docs/theory.md)
    const double Ei = E_[s], vi = v0_[s];
    const Mat<D>& Pi = P_[s];  // V0_i P_i
    Vec<D> f = Vec<D>::Zero();
    double kappa = 0, stored = 0;
    for (std::size_t k = start_[s]; k < start_[s + 1]; ++k) {
      const int t = nj_[k];
      const unsigned mk = mask_[k];
      // G15 Eq. 24: f_i = sum_j V_i V_j (P_i L_i grad W_i(X_ij) - P_j L_j grad W_j(X_ji));
      // g_ij holds V_j L_i grad W: anti-symmetric pair terms, linear momentum exact. An image
      // j' = R j: P_j' g_j'i = R (P_j g_j(Ri)).
      const Vec<D> fj = P_[t] * gr_[k];
      f.noalias() += Pi * g_[k] - (mk ? image(fj, mk, false) : fj);
      if (alpha <= 0) continue;
      // G15 Eq. 25-27: error of the pair against F_i X_ij and F_j X_ij (X_ji = -X_ij).
      const int j = idx_[t];
      const Vec<D> xij = (mk ? image(x[j], mk, true) : x[j]) - x[i];
      const double ir = 1.0 / xij.norm();
      const Vec<D>& X = X_[k];
      const double di = (F_[s] * X - xij).dot(xij) * ir;
      const double dj = ((mk ? image(F_[t], mk) : F_[t]) * X - xij).dot(xij) * ir;
      const double Ej = E_[t];
      const double vw = v0_[t] * w_[k];  // V_j W(X_ij) / X_ij^2, W in the reference frame
      // G15 Eq. 32: -1/2 alpha V_i V_j W_ij / X_ij^2 [E_i delta_i + E_j delta_j] x_ij / x_ij
      f += (-0.5 * alpha * vi * vw * (Ei * di + Ej * dj) * ir) * xij;
      const double Eij = 0.5 * (Ei + Ej), dm = 0.5 * (di + dj);
      kappa += vw * Eij;
      stored += vw * Eij * dm * dm;
    }
    a[i] += f / m[i];
    // Springs k_ij = alpha V_i V_j W_ij E / X_ij^2: omega^2 <= 2 sum_j k_ij / m_i (Gershgorin),
    // as the Eulerian hourglass springs (SolidModule::max_dt).
    omega2[i] = 2.0 * alpha * kappa * vi / m[i];
    if (!hge.empty()) hge[i] = 0.25 * alpha * vi * stored;
  }
}

template class TotalLagrangian<2>;
template class TotalLagrangian<3>;

}  // namespace monosph
