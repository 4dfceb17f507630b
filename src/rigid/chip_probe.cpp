#include "chip_probe.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace monosph {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The particles of the body at distances s in `range` along the axis from the point and d in
// [-dp, 5 size] along the normal, binned dp/2 wide in d: extent and the volume-weighted velocity
// relative to the surface per bin, and the volume and volume x speed of them all.
template <int D>
struct Window {
  Vec<D> p0, axis, normal;
  int body = -1;
  double dp = 0, d0 = 0, width = 0;
  std::vector<double> lo, hi, vel;
  double volume = 0, volume_speed = 0;

  Window(Simulation<D>& sim, const ProbeSpec& spec, const Vec<D>& displacement) {
    for (int a = 0; a < D; ++a)
      p0[a] = spec.point[a], axis[a] = spec.axis[a], normal[a] = spec.normal[a];
    p0 += displacement;
    for (std::size_t b = 0; b < sim.bodies().size(); ++b)
      if (sim.bodies()[b].name == spec.target) body = static_cast<int>(b);
    dp = sim.scene().dp, d0 = -dp, width = 0.5 * dp;
    const std::size_t nb = static_cast<std::size_t>(std::ceil((5 * spec.size - d0) / width));
    lo.assign(nb, kInf), hi.assign(nb, -kInf), vel.assign(nb * D, 0.0);
  }
  // Whether particle position r (from p0) lies in the window; its coordinates s and d.
  bool inside(const ProbeSpec& spec, const Vec<D>& r, double& s, double& d) const {
    s = r.dot(axis), d = r.dot(normal);
    return s >= spec.range[0] && s <= spec.range[1] && d >= d0 && d < 5 * spec.size;
  }
  void fill(Simulation<D>& sim, const ProbeSpec& spec, const Vec<D>& velocity) {
    auto& p = sim.particles();
    auto x = p.x();
    auto v = p.v();
    auto m = p.m();
    auto rho = p.rho();
    auto bd = p.body();
    const std::size_t nb = lo.size();
    for (std::size_t i = 0; i < sim.owned(); ++i) {
      double s, d;
      if (bd[i] != body || !inside(spec, x[i] - p0, s, d)) continue;
      const Vec<D> vr = v[i] - velocity;
      const double vol = m[i] / rho[i];
      volume += vol, volume_speed += vol * vr.norm();
      const std::size_t k = std::min(nb - 1, static_cast<std::size_t>((d - d0) / width));
      lo[k] = std::min(lo[k], d), hi[k] = std::max(hi[k], d);
      for (int a = 0; a < D; ++a) vel[k * D + a] += vol * vr[a];
    }
  }
};

// A run of occupied bins without a gap wider than 1.5 dp: extent in d and summed flow.
template <int D>
struct Run {
  double first = kInf, last = -kInf;
  Vec<D> flow = Vec<D>::Zero();
  double extent(double dp) const { return first < kInf ? last - first + dp : 0.0; }
};

// The first run (widest = false) or the widest one.
template <int D>
Run<D> find_run(const Window<D>& w, bool widest) {
  Run<D> run, best;
  const std::size_t nb = w.lo.size();
  for (std::size_t k = 0; k <= nb; ++k) {
    const bool occupied = k < nb && w.hi[k] >= w.lo[k];
    if (occupied && run.first < kInf && w.lo[k] - run.last <= 1.5 * w.dp) {
      run.last = w.hi[k];
    } else if (occupied || k == nb) {
      if (run.extent(w.dp) > best.extent(w.dp)) best = run;
      if ((run.first < kInf && !widest) || k == nb) break;
      run = Run<D>{w.lo[k], w.hi[k], Vec<D>::Zero()};
    } else {
      continue;
    }
    for (int a = 0; a < D; ++a) run.flow[a] += w.vel[k * D + a];
  }
  return best;
}

// A strip of thickness t flowing along e: its particles at the least and the greatest d lie at
// s_first and s_last along the axis, and extent = (t + (s_last - s_first)(e.normal))/(e.axis),
// so t = |extent (e.axis) - (s_last - s_first)(e.normal)|. The positions along the axis come
// from a second pass (the extreme particles may be on other ranks).
template <int D>
double section_thickness(Simulation<D>& sim, const ProbeSpec& spec, const Window<D>& w,
                         const Run<D>& run) {
  const double f = run.flow.norm();
  if (!(f > 0)) return 0.0;
  auto x = sim.particles().x();
  auto bd = sim.particles().body();
  double at[4] = {0, 0, 0, 0};  // sum and count of s at d = first, at d = last
  for (std::size_t i = 0; i < sim.owned(); ++i) {
    double s, d;
    if (bd[i] != w.body || !w.inside(spec, x[i] - w.p0, s, d)) continue;
    if (d == run.first) at[0] += s, at[1] += 1;
    if (d == run.last) at[2] += s, at[3] += 1;
  }
  sim.comm().sum(std::span<double>(at));
  const double ds = at[1] > 0 && at[3] > 0 ? at[2] / at[3] - at[0] / at[1] : 0.0;
  const Vec<D> e = run.flow / f;
  return std::abs(run.extent(w.dp) * e.dot(w.axis) - ds * e.dot(w.normal));
}

}  // namespace

template <int D>
double chip_ratio(Simulation<D>& sim, const ProbeSpec& spec, const Vec<D>& displacement,
                  const Vec<D>& velocity) {
  Window<D> w(sim, spec, displacement);
  w.fill(sim, spec, velocity);
  const Comm& comm = sim.comm();
  if (spec.method == "flow") {
    // Steady chip, mass conservation: rho vc h = rho v_chip t_c, so t_c / h = vc / v_chip with
    // v_chip the mean speed over the chip's section (a curled chip turning rigidly too).
    double sum[2] = {w.volume, w.volume_speed};
    comm.sum(std::span<double>(sum));
    return sum[1] > 0 ? velocity.norm() * sum[0] / sum[1] : 0.0;
  }
  comm.min(std::span<double>(w.lo)), comm.max(std::span<double>(w.hi));
  comm.sum(std::span<double>(w.vel));
  // layer: the run from the nearest particle out (a curled-back part further out is not the
  // layer), thickness max d - min d + dp. section: the widest run, normal to its mean flow.
  if (spec.method != "section") return find_run(w, false).extent(w.dp) / spec.size;
  return section_thickness(sim, spec, w, find_run(w, true)) / spec.size;
}

template double chip_ratio<2>(Simulation<2>&, const ProbeSpec&, const Vec<2>&, const Vec<2>&);
template double chip_ratio<3>(Simulation<3>&, const ProbeSpec&, const Vec<3>&, const Vec<3>&);

}  // namespace monosph
