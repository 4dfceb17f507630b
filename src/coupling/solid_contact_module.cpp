#include "solid_contact_module.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <span>

#include "contact_law.hpp"
#include "core/hertz.hpp"

namespace monosph {

namespace {

// A contact pair: two solid particles of different continua (interaction groups).
bool contact_pair(std::int64_t pi, std::int64_t pj, int gi, int gj) {
  return pi == kSolid && pj == kSolid && gi != gj;
}

}  // namespace

template <int D>
SolidContactModule<D>::SolidContactModule(Simulation<D>& sim) {
  auto& p = sim.particles();
  kcf_ = p.add_field("solid_contact_force", D, FieldType::Real, true);  // per depth in 2D
  p.set_meaning({kcf_}, phase_bit(kSolid));
  spec_ = module_params<SolidContactSpec>(sim.scene().params);
  dc_ = spec_.distance * sim.dp();
  depth_ = D == 2 ? sim.dp() : 1.0;  // 2D: per metre of depth, t_z = dp (equations.md Sect. 0)
  const auto& mats = sim.materials();
  nmat_ = mats.size();
  estar_.resize(nmat_ * nmat_);
  for (std::size_t a = 0; a < nmat_; ++a)
    for (std::size_t b = 0; b < nmat_; ++b)  // Johnson 1985, Eq. 4.23
      estar_[a * nmat_ + b] = 1.0 / (compliance(mats[a]) + compliance(mats[b]));
}

template <int D>
double SolidContactModule<D>::pair_force(double r, int mi, int mj) const {
  // Johnson 1985, Eq. 4.23 for two spheres of diameter d_c: R* = d_c/4.
  return r < dc_ ? hertz_force(estar_[idx(mi, mj)], 0.25 * dc_, dc_ - r) / depth_ : 0.0;
}

template <int D>
double SolidContactModule<D>::pair_energy(double r, int mi, int mj) const {
  return r < dc_ ? hertz_energy(estar_[idx(mi, mj)], 0.25 * dc_, dc_ - r) / depth_ : 0.0;
}

template <int D>
void SolidContactModule<D>::forces(Simulation<D>& sim) {
  auto& p = sim.particles();
  const auto& pl = sim.pairs();
  const auto& grp = sim.group();
  auto ph = p.phase();
  auto x = p.x();
  auto v = p.v();
  auto a = p.a();
  auto m = p.m();
  auto mt = p.material();
  auto id = p.id();
  auto cf = p.template view<Vec<D>>(kcf_);
  const std::size_t n = std::min(p.size(), pl.count.size()), own = sim.owned();
  const double dc = dc_, rstar = 0.25 * dc_, zeta = spec_.damping, mu = spec_.friction;
  const double dt = sim.dt(), delta_floor = 0.05 * dc_;  // step stiffness at >= 0.1 R overlap
  long npairs = 0, nnear = 0;
  double w2 = 0, worst = 0;
#pragma omp parallel for schedule(runtime) reduction(+ : npairs, nnear) reduction(max : w2, worst)
  for (std::size_t i = 0; i < n; ++i) {
    cf[i].setZero();
    if (ph[i] != kSolid) continue;
    Vec<D> f = Vec<D>::Zero();
    for (std::size_t k = pl.begin(i); k < pl.end(i); ++k) {
      const int j = pl.j[k];
      if (!contact_pair(ph[i], ph[j], grp[i], grp[j])) continue;
      const Vec<D> rij = pl.r(x, i, k);
      const double r = rij.norm(), es = estar_[idx(mt[i], mt[j])];
      // Time-step stiffness k/m of this particle for every pair within the support (an
      // approaching pair), at an overlap of at least 0.1 R.
      const double kn = hertz_stiffness(es, rstar, std::max(dc - r, delta_floor)) / depth_;
      if (i < own) {
        w2 = std::max(w2, kn / m[i]);
        if (id[i] < id[j]) ++nnear;  // each pair once, on any number of ranks
      }
      if (r >= dc || !(r > 0)) continue;  // repulsive only: no force at or beyond d_c
      const Vec<D> nrm = rij / r;         // from j to i
      const double ms = m[i] * m[j] / (m[i] + m[j]);
      double fn = pair_force(r, static_cast<int>(mt[i]), static_cast<int>(mt[j]));
      if (zeta > 0) {
        // Normal dashpot -2 zeta sqrt(k m*) v_n, k = dF/d(delta) = 1.5 F/delta (Tsuji et al. 1992),
        // never pulling (the pair force stays repulsive).
        const double kd = 1.5 * fn / (dc - r);
        fn = std::max(0.0, fn - 2 * zeta * std::sqrt(kd * ms) * (v[i] - v[j]).dot(nrm));
      }
      f += fn * nrm;
      if (mu > 0) f += friction<D>(v[i] - v[j], nrm, fn, mu, ms, dt);  // Cundall & Strack 1979
      if (i < own) {
        worst = std::max(worst, dc - r);
        if (id[i] < id[j]) ++npairs;
      }
    }
    cf[i] = f;
    a[i] += f / m[i];
  }
  const Comm& comm = sim.comm();
  pairs_ = comm.sum(npairs);
  near_ = comm.sum(nnear);
  omega2_ = comm.max(w2);
  max_overlap_ = comm.max(worst);
}

template <int D>
double SolidContactModule<D>::max_dt(Simulation<D>&) {
  // A contact is a spring of frequency sqrt(k/m): dt <= 0.1 pi sqrt(m/k), 20 steps per period
  // (equations.md Sect. 7, as the grain contact and the self-contact).
  if (!(omega2_ > 0)) return std::numeric_limits<double>::infinity();
  return 0.1 * std::numbers::pi / std::sqrt(omega2_);
}

template <int D>
double SolidContactModule<D>::potential_energy(Simulation<D>& sim) {
  // Serial over the owned particles in index order (the same for any thread count); each side of
  // a pair adds half, so a pair split between two ranks counts once.
  auto& p = sim.particles();
  const auto& pl = sim.pairs();
  const auto& grp = sim.group();
  auto ph = p.phase();
  auto mt = p.material();
  auto x = p.x();
  double e = 0;
  const std::size_t own = std::min(sim.owned(), pl.count.size());
  for (std::size_t i = 0; i < own; ++i)
    for (std::size_t k = pl.begin(i); k < pl.end(i); ++k) {
      const int j = pl.j[k];
      if (contact_pair(ph[i], ph[j], grp[i], grp[j]))
        e += 0.5 *
             pair_energy(pl.r(x, i, k).norm(), static_cast<int>(mt[i]), static_cast<int>(mt[j]));
    }
  return e;
}

template <int D>
std::vector<std::string> SolidContactModule<D>::probe_columns(const ProbeSpec& s) const {
  if (s.type == "solid_contact_pairs" || s.type == "solid_contact_neighbours") return {""};
  if (s.type == "solid_contact_force") return axis_columns(D);
  return {};
}

template <int D>
void SolidContactModule<D>::probe(Simulation<D>& sim, const ProbeSpec& s,
                                  std::vector<double>& out) {
  if (s.type != "solid_contact_force") {
    out.push_back(static_cast<double>(s.type == "solid_contact_pairs" ? pairs_ : near_));
    return;
  }
  // The contact force on the owned particles of `body` (all solid particles without one), summed
  // in index order and over the ranks. Per metre of depth in 2D.
  int body = -1;
  for (std::size_t b = 0; b < sim.bodies().size(); ++b)
    if (sim.bodies()[b].name == s.body) body = static_cast<int>(b);
  auto& p = sim.particles();
  auto bd = p.body();
  auto cf = p.template view<Vec<D>>(kcf_);
  std::array<double, D> sum{};
  for (std::size_t i = 0; i < sim.owned(); ++i)
    if (body < 0 || bd[i] == body)
      for (int c = 0; c < D; ++c) sum[c] += cf[i][c];
  sim.comm().sum(std::span<double>(sum.data(), D));
  for (int c = 0; c < D; ++c) out.push_back(sum[c]);
}

template class SolidContactModule<2>;
template class SolidContactModule<3>;

}  // namespace monosph
