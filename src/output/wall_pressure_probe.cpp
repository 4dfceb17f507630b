#include "output/wall_pressure_probe.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace monosph {

namespace {

// Two unit vectors perpendicular to n and to each other (3D).
void tangents(const Vec<3>& n, Vec<3>& e1, Vec<3>& e2) {
  int k = 0;  // the coordinate axis least aligned with n
  for (int a = 1; a < 3; ++a)
    if (std::abs(n[a]) < std::abs(n[k])) k = a;
  Vec<3> ax = Vec<3>::Zero();
  ax[k] = 1;
  e1 = n.cross(ax).normalized();
  e2 = n.cross(e1);
}

// Distance from x to the nearest particle of `body` (owned particles of every rank).
template <int D>
double nearest_of_body(Simulation<D>& sim, int body, const Vec<D>& x) {
  auto& p = sim.particles();
  auto px = p.x();
  auto bd = p.body();
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < sim.owned(); ++i)
    if (bd[i] == body) best = std::min(best, (px[i] - x).squaredNorm());
  return std::sqrt(sim.comm().min(best));
}

}  // namespace

template <int D>
std::vector<Vec<D>> sensor_points(const Vec<D>& c, const Vec<D>& n, double size, double spacing) {
  const int m = std::clamp(static_cast<int>(std::ceil(size / spacing)), 10, D == 2 ? 400 : 64);
  std::vector<Vec<D>> pts;
  auto at = [&](int k) { return size * ((k + 0.5) / m - 0.5); };  // midpoints of m equal parts
  if constexpr (D == 2) {
    const Vec<2> t(-n[1], n[0]);
    for (int k = 0; k < m; ++k) pts.push_back(c + at(k) * t);
  } else {
    Vec<3> e1, e2;
    tangents(n, e1, e2);
    for (int a = 0; a < m; ++a)  // the cells of an m x m grid whose centres lie in the disc
      for (int b = 0; b < m; ++b)
        if (at(a) * at(a) + at(b) * at(b) <= 0.25 * size * size)
          pts.push_back(c + at(a) * e1 + at(b) * e2);
  }
  return pts;
}

template <int D>
WallPressureProbe<D>::WallPressureProbe(Simulation<D>& sim, const ProbeSpec& spec, int body,
                                        const std::string& where) {
  kpw_ = sim.particles().find("wall_pressure");
  if (kpw_ < 0)
    throw InputError(where + ".type: 'wall_pressure' needs the fluid module (a fluid body)");
  Vec<D> n;
  for (int a = 0; a < D; ++a) centre_[a] = spec.point[a], n[a] = spec.axis[a];
  const double dp = sim.dp();
  const std::string& name = sim.bodies()[body].name;
  // A point of the face is at most half a lattice diagonal, sqrt(D) dp / 2, from the outer layer.
  const double d0 = nearest_of_body(sim, body, centre_), limit = (0.5 * std::sqrt(D) + 0.05) * dp;
  if (d0 > limit)
    throw InputError(where + ".center: not on the face of '" + name +
                     fmt::format("' (its nearest particle is {:g} m away; on a face it is at most "
                                 "(sqrt({}) / 2 + 0.05) dp = {:g} m)",
                                 d0, D, limit));
  const double din = nearest_of_body(sim, body, Vec<D>(centre_ - 0.5 * dp * n));
  const double dout = nearest_of_body(sim, body, Vec<D>(centre_ + 0.5 * dp * n));
  if (!(din < dout))
    throw InputError(where + ".normal: points into '" + name +
                     "'; it must point from the wall face into the fluid");
  pts_ = sensor_points<D>(centre_, n, spec.size, 0.25 * dp);
  reach_ = 0.5 * spec.size + sim.kernel().radius();
}

template <int D>
double WallPressureProbe<D>::sample(Simulation<D>& sim) const {
  auto& p = sim.particles();
  auto x = p.x();
  auto m = p.m();
  auto rho = p.rho();
  // a fluid particle's own pressure, a wall particle's extrapolated one (the Adami wall's field)
  auto pressure = [ph = p.phase(), pr = p.p(), pw = p.template view<double>(kpw_)](std::size_t i) {
    return ph[i] == kFluid ? pr[i] : pw[i];
  };
  const Kernel<D>& W = sim.kernel();
  const double R = W.radius();
  const std::size_t np = pts_.size();
  std::vector<double> s(2 * np, 0.0);  // per point: sum p V W, sum V W
  for (std::size_t i = 0; i < sim.owned(); ++i) {
    if ((x[i] - centre_).squaredNorm() >= reach_ * reach_) continue;
    const double v = m[i] / rho[i], pi = pressure(i);
    for (std::size_t k = 0; k < np; ++k) {
      const double r = (x[i] - pts_[k]).norm();
      if (r >= R) continue;
      const double w = v * W.w(r);
      s[2 * k] += pi * w;
      s[2 * k + 1] += w;
    }
  }
  sim.comm().sum(std::span<double>(s));
  double mean = 0;
  for (std::size_t k = 0; k < np; ++k)
    if (s[2 * k + 1] > 0) mean += s[2 * k] / s[2 * k + 1];
  return mean / static_cast<double>(np);
}

template class WallPressureProbe<2>;
template class WallPressureProbe<3>;
template std::vector<Vec<2>> sensor_points<2>(const Vec<2>&, const Vec<2>&, double, double);
template std::vector<Vec<3>> sensor_points<3>(const Vec<3>&, const Vec<3>&, double, double);

}  // namespace monosph
