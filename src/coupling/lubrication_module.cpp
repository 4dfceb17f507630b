#include "lubrication_module.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "rigid/cluster_module.hpp"

namespace monosph {

namespace {

bool film_partner(std::int64_t phase) {
  return phase == kSolid || phase == kWall || phase == kRigid;
}

}  // namespace

template <int D>
LubricationModule<D>::LubricationModule(Simulation<D>& sim) {
  const auto& spec = module_params<LubricationSpec>(sim.scene().params);
  mu_ = spec.viscosity;
  hc_ = spec.cutoff * sim.dp();
  hmin_ = spec.min_gap * sim.dp();
  kcl_ = sim.particles().add_field("cluster", 1, FieldType::Int, true);
  nbodies_ = static_cast<long>(sim.bodies().size());
}

template <int D>
double LubricationModule<D>::force(double h, double U, double a) const {
  if (!(h < hc_) || !(U > 0)) return 0.0;
  const double H = std::max(h, hmin_);
  if constexpr (D == 2) {  // Jeffrey & Onishi 1981: 3 sqrt(2) pi mu U (a/h)^1.5, shifted at h_c
    return 3 * std::numbers::sqrt2 * std::numbers::pi * mu_ * U * std::pow(a, 1.5) *
           (std::pow(H, -1.5) - std::pow(hc_, -1.5));
  } else {  // Brenner 1961, leading order: 6 pi mu U a^2 / h, shifted at h_c
    return 6 * std::numbers::pi * mu_ * U * a * a * (1 / H - 1 / hc_);
  }
}

template <int D>
void LubricationModule<D>::radii(Simulation<D>& sim) {
  // Radius of each cluster from its inertia: disc I = M a^2/2, sphere tr(I) = 6/5 M a^2.
  for (const auto& m : sim.modules()) {
    const auto* cm = dynamic_cast<const ClusterModule<D>*>(m.get());
    if (!cm) continue;
    radius_.resize(cm->size());
    mass_.resize(cm->size());
    for (std::size_t c = 0; c < cm->size(); ++c) {
      const auto& k = cm->cluster(c);
      mass_[c] = k.mass;
      if constexpr (D == 2)
        radius_[c] = std::sqrt(2 * k.inertia / k.mass);
      else
        radius_[c] = std::sqrt(5 * k.inertia_body.trace() / (6 * k.mass));
    }
  }
  film_.assign(radius_.size(), Film{});
}

template <int D>
void LubricationModule<D>::on_rebuild(Simulation<D>& sim) {
  auto& p = sim.particles();
  auto ph = p.phase();
  rigid_.clear();
  for (std::size_t i = 0; i < sim.owned(); ++i)
    if (ph[i] == kRigid) rigid_.push_back(i);
}

template <int D>
void LubricationModule<D>::find_films(Simulation<D>& sim) {
  // Per cluster: the closest pair with a particle of another body or cluster, its gap h = r - dp
  // (particles are cells of side dp), its approach speed and the partner. Each rigid particle's
  // closest pair in parallel, then per cluster in index order: the same for any thread count.
  auto& p = sim.particles();
  const auto& pl = sim.pairs();
  auto ph = p.phase();
  auto bd = p.body();
  auto v = p.v();
  auto x = p.x();
  auto cl = p.template view<std::int64_t>(kcl_);
  const double dp = sim.dp(), inf = std::numeric_limits<double>::infinity();
  const Film none{inf, -inf};  // no partner: any pair is closer
  // Smaller gap first, then the faster approach; the first such pair in (i, k) order wins.
  auto closer = [](const Film& a, const Film& b) {
    return a.gap < b.gap || (a.gap == b.gap && a.speed > b.speed);
  };
  closest_.resize(rigid_.size());
#pragma omp parallel for schedule(static)
  for (std::size_t q = 0; q < rigid_.size(); ++q) {
    const std::size_t i = rigid_[q];
    Film f = none;
    for (std::size_t k = pl.begin(i); k < pl.end(i); ++k) {
      const int j = pl.j[k];
      if (!film_partner(ph[j]) || (ph[j] == kRigid && cl[j] == cl[i])) continue;
      const Vec<D> rij = pl.r(x, i, k);
      const double r = rij.norm();
      const Film g{r - dp, -(v[i] - v[j]).dot(rij) / r};  // speed > 0: closing
      if (!closer(g, f)) continue;
      f = g, f.partner = object(bd[j], cl[j]);
      const double a = radius_[cl[i]];
      f.radius = cl[j] >= 0 ? a * radius_[cl[j]] / (a + radius_[cl[j]]) : a;
    }
    closest_[q] = f;
  }
  std::fill(film_.begin(), film_.end(), none);
  for (std::size_t q = 0; q < rigid_.size(); ++q) {
    Film& f = film_[cl[rigid_[q]]];
    if (closer(closest_[q], f)) f = closest_[q];
  }
  const Comm& comm = sim.comm();
  const std::size_t nc = film_.size();
  if (comm.parallel()) {  // the closest pair over all ranks; its speed, radius and partner
    buf_.resize(nc);
    for (std::size_t c = 0; c < nc; ++c) buf_[c] = film_[c].gap;
    comm.min(buf_);
    std::vector<double> rest(3 * nc, -inf);
    for (std::size_t c = 0; c < nc; ++c)
      if (film_[c].gap == buf_[c])
        rest[3 * c] = film_[c].speed, rest[3 * c + 1] = film_[c].radius,
                 rest[3 * c + 2] = static_cast<double>(film_[c].partner);
    comm.max(rest);
    for (std::size_t c = 0; c < nc; ++c)
      film_[c] =
          Film{buf_[c], rest[3 * c], rest[3 * c + 1], 0, 0, static_cast<long>(rest[3 * c + 2])};
  }
  for (auto& f : film_) f.force = f.partner >= 0 ? force(f.gap, f.speed, f.radius) : 0.0;
}

template <int D>
double LubricationModule<D>::share(const Film& f, double h, double vn, double mstar,
                                   double dt) const {
  // The pair's part of the film force, at most what stops its approach within one step: the
  // damper c = F/U integrated exactly, m* vn (1 - exp(-c dt/m*))/dt.
  const double w = 1.0 / std::pow(std::max(h, hmin_), 2);
  const double fij = f.force * w / f.weight;
  if (!(vn > 0) || !(dt > 0)) return 0.0;
  const double c = fij / f.speed;
  return std::min(fij, mstar * vn * (1 - std::exp(-c * dt / mstar)) / dt);
}

template <int D>
void LubricationModule<D>::forces(Simulation<D>& sim) {
  if (radius_.empty()) radii(sim);
  total_.setZero();
  if (film_.empty()) return;
  find_films(sim);
  // Most steps no grain is within h_c of a surface: no pass over the particles then.
  if (std::none_of(film_.begin(), film_.end(), [](const Film& f) { return f.force > 0; })) return;
  auto& p = sim.particles();
  const auto& pl = sim.pairs();
  auto ph = p.phase();
  auto bd = p.body();
  auto x = p.x();
  auto v = p.v();
  auto a = p.a();
  auto m = p.m();
  auto cl = p.template view<std::int64_t>(kcl_);
  const double dp = sim.dp(), dt = sim.dt();
  // A film pair: a rigid particle of cluster c and a particle of its partner, closer than h_c.
  auto in_film = [&](std::size_t i, int j, double h) {
    const Film& f = film_[cl[i]];
    return f.force > 0 && h < hc_ && object(bd[j], cl[j]) == f.partner;
  };
  for (std::size_t i : rigid_)
    for (std::size_t k = pl.begin(i); k < pl.end(i); ++k) {
      const int j = pl.j[k];
      const double h = pl.r(x, i, k).norm() - dp;
      if (film_partner(ph[j]) && in_film(i, j, h))
        film_[cl[i]].weight += 1.0 / std::pow(std::max(h, hmin_), 2);
    }
  const std::size_t nc = film_.size();
  if (sim.comm().parallel()) {
    buf_.resize(nc);
    for (std::size_t c = 0; c < nc; ++c) buf_[c] = film_[c].weight;
    sim.comm().sum(buf_);
    for (std::size_t c = 0; c < nc; ++c) film_[c].weight = buf_[c];
  }
  // Reduced mass of a pair: a cluster particle moves with its cluster's mass; walls do not move.
  auto mass_of = [&](int j) { return cl[j] >= 0 ? mass_[cl[j]] : m[j]; };
  const std::size_t own = sim.owned();
  flub_.assign(own, Vec<D>::Zero());
#pragma omp parallel for schedule(runtime)
  for (std::size_t i = 0; i < own; ++i) {
    if (!film_partner(ph[i])) continue;
    Vec<D> fi = Vec<D>::Zero();
    for (std::size_t k = pl.begin(i); k < pl.end(i); ++k) {
      const int j = pl.j[k];
      if (!film_partner(ph[j])) continue;
      const Vec<D> rij = pl.r(x, i, k);
      const double r = rij.norm(), h = r - dp;
      // The film this pair belongs to: of i's cluster or of j's (two clusters: the lower index).
      const bool by_i = ph[i] == kRigid && in_film(i, j, h);
      const bool by_j = ph[j] == kRigid && in_film(j, static_cast<int>(i), h);
      if (!by_i && !by_j) continue;
      const bool rigid_side = by_i && (!by_j || cl[i] < cl[j]);
      const std::size_t c = rigid_side ? cl[i] : cl[j];
      const std::size_t ri = rigid_side ? i : std::size_t(j), pj = rigid_side ? j : i;
      const double mi = mass_[c], mj = ph[pj] == kWall ? 0.0 : mass_of(static_cast<int>(pj));
      const double mstar = mj > 0 ? mi * mj / (mi + mj) : mi;
      const Vec<D> n = (rigid_side ? 1.0 : -1.0) * rij / r;  // partner -> cluster particle
      const double vn = -(v[ri] - v[pj]).dot(n);
      const double f = share(film_[c], h, vn, mstar, dt);
      fi += (rigid_side ? f : -f) * n;
    }
    flub_[i] = fi;
    if (ph[i] != kWall) a[i] += fi / m[i];  // cluster members: summed by the clusters module
  }
  for (std::size_t i : rigid_) total_ += flub_[i];  // serial: the same for any thread count
}

template <int D>
std::vector<std::string> LubricationModule<D>::probe_columns(const ProbeSpec& s) const {
  if (s.type == "lubrication_gap") return {""};
  if (s.type != "lubrication_force") return {};
  return axis_columns(D);
}

template <int D>
void LubricationModule<D>::probe(Simulation<D>& sim, const ProbeSpec& s, std::vector<double>& out) {
  if (s.type == "lubrication_gap") {  // smallest gap of any cluster to its closest surface
    double g = std::numeric_limits<double>::infinity();
    for (const auto& f : film_) g = std::min(g, f.gap);
    out.push_back(std::isfinite(g) ? g : std::numeric_limits<double>::quiet_NaN());
    return;
  }
  Vec<D> t = total_;
  sim.comm().sum(std::span<double>(t.data(), D));
  for (int k = 0; k < D; ++k) out.push_back(t[k]);
}

template class LubricationModule<2>;
template class LubricationModule<3>;

}  // namespace monosph
