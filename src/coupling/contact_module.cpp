#include "contact_module.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "contact_law.hpp"
#include "core/hertz.hpp"

namespace monosph {

namespace {

// Pairs in contact: a rigid-cluster particle with a solid, a wall or another cluster's particle.
bool contact_pair(std::int64_t pi, std::int64_t pj, std::int64_t cluster_i,
                  std::int64_t cluster_j) {
  if (pi == kRigid) return pj == kSolid || pj == kWall || (pj == kRigid && cluster_j != cluster_i);
  return (pi == kSolid || pi == kWall) && pj == kRigid;
}

}  // namespace

template <int D>
ContactModule<D>::ContactModule(Simulation<D>& sim) {
  auto& p = sim.particles();
  kcl_ = p.add_field("cluster", 1, FieldType::Int, true);
  kcf_ = p.add_field("contact_force", D, FieldType::Real, true);  // per depth in 2D
  p.set_meaning({kcf_}, ~phase_bit(kFluid));
  spec_ = module_params<ContactSpec>(sim.scene().params);
  hertz_ = spec_.law == "hertz";
  dc_ = spec_.distance * sim.dp();
  depth_ = D == 2 ? sim.dp() : 1.0;
  const auto& mats = sim.materials();
  nmat_ = mats.size();
  estar_.resize(nmat_ * nmat_);
  for (std::size_t a = 0; a < nmat_; ++a)
    for (std::size_t b = 0; b < nmat_; ++b)
      estar_[a * nmat_ + b] = 1.0 / (compliance(mats[a]) + compliance(mats[b]));
}

template <int D>
double ContactModule<D>::pair_force(double r, int mi, int mj, double m_i, double m_j) const {
  if (r >= dc_) return 0.0;
  if (hertz_) {
    const double delta = dc_ - r, rstar = 0.25 * dc_;  // two spheres of radius d_c/2
    return hertz_force(estar_[idx(mi, mj)], rstar, delta) / depth_;
  }
  const double q = dc_ / r, mij = 2 * m_i * m_j / (m_i + m_j);
  return mij * spec_.strength * (std::pow(q, spec_.p1) - std::pow(q, spec_.p2)) / r;
}

template <int D>
double ContactModule<D>::pair_energy(double r, int mi, int mj, double m_i, double m_j) const {
  if (r >= dc_) return 0.0;
  if (hertz_) return hertz_energy(estar_[idx(mi, mj)], 0.25 * dc_, dc_ - r) / depth_;
  // Monaghan 1994: F = m_ij D (q^p1 - q^p2)/r with q = d_c/r; U(r) = int_r^d_c F ds
  // = m_ij D [(q^p1 - 1)/p1 - (q^p2 - 1)/p2].
  const double q = dc_ / r, mij = 2 * m_i * m_j / (m_i + m_j);
  const double p1 = spec_.p1, p2 = spec_.p2;
  return mij * spec_.strength * ((std::pow(q, p1) - 1) / p1 - (std::pow(q, p2) - 1) / p2);
}

template <int D>
double ContactModule<D>::potential_energy(Simulation<D>& sim) {
  // Serial over the owned particles in index order (the same for any thread count); each side of
  // a pair adds half, so a pair split between two ranks counts once.
  auto& p = sim.particles();
  const auto& pl = sim.pairs();
  auto ph = p.phase();
  auto m = p.m();
  auto mt = p.material();
  auto cl = p.template view<std::int64_t>(kcl_);
  auto x = p.x();
  double e = 0;
  for (std::size_t i = 0; i < sim.owned(); ++i)
    for (std::size_t k = pl.begin(i); k < pl.end(i); ++k) {
      const int j = pl.j[k];
      if (!contact_pair(ph[i], ph[j], cl[i], cl[j])) continue;
      e += 0.5 * pair_energy(pl.r(x, i, k).norm(), static_cast<int>(mt[i]), static_cast<int>(mt[j]),
                             m[i], m[j]);
    }
  return e;
}

template <int D>
void ContactModule<D>::forces(Simulation<D>& sim) {
  auto& p = sim.particles();
  const auto& pl = sim.pairs();
  auto ph = p.phase();
  auto x = p.x();
  auto v = p.v();
  auto a = p.a();
  auto m = p.m();
  auto mt = p.material();
  auto cl = p.template view<std::int64_t>(kcl_);
  auto cf = p.template view<Vec<D>>(kcf_);
  auto id = p.id();
  const std::size_t n = p.size(), own = sim.owned();  // sums over owned particles (MPI)
  touch_.resize(n);
  near_.resize(n);
  const bool hertz = hertz_;
  const double dc = dc_, release = 1.1 * dc_, zeta = spec_.damping, mu = spec_.friction;
  const double dt = sim.dt();
  const double delta_floor = 0.05 * dc_;  // stiffness for the step at >= 0.1 R overlap
  long npairs = 0;
  double w2 = 0, worst = 0;
#pragma omp parallel for schedule(runtime) reduction(+ : npairs) reduction(max : w2, worst)
  for (std::size_t i = 0; i < n; ++i) {
    const auto pi = ph[i];
    cf[i].setZero();
    touch_[i] = near_[i] = 0;
    if (pi != kRigid && pi != kSolid && pi != kWall) continue;
    Vec<D> f = Vec<D>::Zero();
    for (std::size_t k = pl.begin(i); k < pl.end(i); ++k) {
      const int j = pl.j[k];
      const auto pj = ph[j];
      if (!contact_pair(pi, pj, cl[i], cl[j])) continue;
      const Vec<D> rij = pl.r(x, i, k);
      const double r = rij.norm();
      // Time-step stiffness k/m of this particle, at an overlap of at least 0.1 R.
      if (pi != kWall) {
        double kn;
        if (hertz) {
          const double delta = std::max(dc - r, delta_floor);
          kn = hertz_stiffness(estar_[idx(mt[i], mt[j])], 0.25 * dc, delta) / depth_;
        } else {
          const double re = std::min(r, 0.9 * dc), q = dc / re;
          const double mij = 2 * m[i] * m[j] / (m[i] + m[j]);
          kn = mij * spec_.strength *
               std::abs(-(spec_.p1 + 1) * std::pow(q, spec_.p1) +
                        (spec_.p2 + 1) * std::pow(q, spec_.p2)) /
               (re * re);
        }
        if (i < own) w2 = std::max(w2, kn / m[i]);
      }
      if (pi == kRigid && pj != kRigid && r < release) near_[i] = 1;
      if (r >= dc) continue;
      const Vec<D> nrm = rij / r;  // from j to i
      double fn = pair_force(r, static_cast<int>(mt[i]), static_cast<int>(mt[j]), m[i], m[j]);
      if (hertz && zeta > 0) {
        // Normal dashpot -2 zeta sqrt(k m*) v_n, k = dF/d(delta) = 1.5 F/delta (Tsuji et al. 1992).
        const double kn = 1.5 * fn / (dc - r), ms = m[i] * m[j] / (m[i] + m[j]);
        fn = std::max(0.0, fn - 2 * zeta * std::sqrt(kn * ms) * (v[i] - v[j]).dot(nrm));
      }
      f += fn * nrm;
      if (mu > 0) f += friction<D>(v[i] - v[j], nrm, fn, mu, m[i] * m[j] / (m[i] + m[j]), dt);
      if (i < own) {
        worst = std::max(worst, dc - r);
        if (id[i] < id[j]) ++npairs;  // each pair once, on any number of ranks
      }
      if (pi == kRigid && pj != kRigid) touch_[i] = 1;
    }
    cf[i] = f;
    if (pi != kWall) a[i] += f / m[i];  // walls move as prescribed
  }
  const Comm& comm = sim.comm();
  pairs_ = comm.sum(npairs);
  omega2_ = comm.max(w2);
  max_overlap_ = comm.max(worst);
  // Impacts: a cluster that touches a solid or wall body now and was free before (released only
  // when no member is within 1.1 d_c any more). Serial over the rigid particles, in index order.
  std::fill(touching_.begin(), touching_.end(), 0);
  std::fill(close_.begin(), close_.end(), 0);
  for (std::size_t i : rigid_) {
    if (i >= own) continue;
    touching_[cl[i]] |= touch_[i];
    close_[cl[i]] |= near_[i];
  }
  if (comm.parallel()) {     // a cluster touches if any of its members does, on any rank
    auto& tc = reduce_buf_;  // kept between steps: no allocation
    tc.resize(2 * touching_.size());
    for (std::size_t c = 0; c < touching_.size(); ++c)
      tc[2 * c] = touching_[c], tc[2 * c + 1] = close_[c];
    comm.max(tc);
    for (std::size_t c = 0; c < touching_.size(); ++c)
      touching_[c] = tc[2 * c] > 0, close_[c] = tc[2 * c + 1] > 0;
  }
  for (std::size_t c = 0; c < in_contact_.size(); ++c) {
    if (touching_[c] && !in_contact_[c]) ++impacts_, in_contact_[c] = 1;
    if (!close_[c]) in_contact_[c] = 0;
  }
}

template <int D>
void ContactModule<D>::on_rebuild(Simulation<D>& sim) {
  // Rigid particles and the number of clusters (they never change; the order may).
  auto& p = sim.particles();
  auto ph = p.phase();
  auto cl = p.template view<std::int64_t>(kcl_);
  rigid_.clear();
  std::size_t ncl = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (ph[i] == kRigid && cl[i] >= 0)
      rigid_.push_back(i), ncl = std::max<std::size_t>(ncl, cl[i] + 1);
  ncl = static_cast<std::size_t>(sim.comm().max(static_cast<long>(ncl)));  // some on other ranks
  in_contact_.resize(ncl, 0);
  touching_.assign(ncl, 0);
  close_.assign(ncl, 0);
}

template <int D>
double ContactModule<D>::max_dt(Simulation<D>&) {
  // A contact is a spring of frequency sqrt(k/m): dt <= 0.1 pi sqrt(m/k) (20 steps per period,
  // equations.md Sect. 7), with k at the largest overlap (at least 0.1 R).
  if (!(omega2_ > 0)) return std::numeric_limits<double>::infinity();
  return 0.1 * std::numbers::pi / std::sqrt(omega2_);
}

template <int D>
std::vector<std::string> ContactModule<D>::probe_columns(const ProbeSpec& s) const {
  if (s.type == "grain_impacts" || s.type == "contact_pairs") return {""};
  return {};
}

template <int D>
void ContactModule<D>::probe(Simulation<D>&, const ProbeSpec& s, std::vector<double>& out) {
  out.push_back(s.type == "grain_impacts" ? static_cast<double>(impacts_)
                                          : static_cast<double>(pairs_));
}

template <int D>
void ContactModule<D>::save_state(std::map<std::string, double>& s) const {
  s["contact.impacts"] = static_cast<double>(impacts_);
  for (std::size_t c = 0; c < in_contact_.size(); ++c)
    s[fmt::format("contact.in_contact.{}", c)] = in_contact_[c];
}

template <int D>
void ContactModule<D>::load_state(Simulation<D>&, const std::map<std::string, double>& s) {
  auto it = s.find("contact.impacts");
  impacts_ = it == s.end() ? 0 : static_cast<long>(it->second);
  in_contact_.clear();
  for (std::size_t c = 0;; ++c) {
    auto f = s.find(fmt::format("contact.in_contact.{}", c));
    if (f == s.end()) break;
    in_contact_.push_back(f->second != 0);
  }
}

template class ContactModule<2>;
template class ContactModule<3>;

}  // namespace monosph
