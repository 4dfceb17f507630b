#include "rigid_surface_module.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace monosph {

template <int D>
RigidSurfaceModule<D>::RigidSurfaceModule(Simulation<D>& sim) {
  const Scene& scene = sim.scene();
  radius_ = 0.5 * scene.dp;          // a sphere of diameter dp (MMB Sect. 3)
  depth_ = D == 2 ? scene.dp : 1.0;  // 2D: the sphere's force per metre of the slab
  for (std::size_t k = 0; k < scene.surfaces.size(); ++k) {
    const SurfaceSpec& spec = scene.surfaces[k];
    const std::string where = "surfaces[" + std::to_string(k) + "] (" + spec.name + ")";
    Surface s;
    s.name = spec.name;
    s.geometry = SurfaceGeometry<D>(surface_elements<D>(spec, where));
    s.friction = spec.friction;
    const double inf = std::numeric_limits<double>::infinity();
    s.friction_cap =
        spec.friction_limit > 0 ? spec.friction_limit * std::pow(scene.dp, D - 1) : inf;
    s.heat_partition = spec.heat_partition;
    s.conductance = spec.heat_transfer * std::pow(scene.dp, D - 1);
    s.temperature = spec.temperature;
    if (((s.friction > 0 && s.heat_partition < 1) || s.conductance > 0) && kq_ < 0) {
      auto& p = sim.particles();
      kT_ = p.add_field("temperature", 1, FieldType::Real, true);  // the solid module's
      kq_ = p.add_field("surface_heating", 1, FieldType::Real, true);
      p.set_meaning({kT_, kq_}, phase_bit(kSolid) | phase_bit(kFluid));
    }
    s.damping = spec.damping;
    for (int a = 0; a < D; ++a) {
      s.velocity_expr.emplace_back(spec.velocity_expr[a], where + ".velocity", scene.variables);
      s.constant = s.constant && !s.velocity_expr.back().depends_on_time();
    }
    s.v0 = velocity_at(s, 0.0);
    if (s.constant) s.velocity_expr.clear();
    for (const Material& m : scene.materials)
      s.e_star.push_back(monosph::contact_modulus(m.bulk_modulus, m.shear_modulus, spec.stiffness,
                                                  spec.poisson_ratio));
    s.velocity = s.v0;
    s_.push_back(std::move(s));
  }
}

// With friction heat or heat transfer the temperature field may be this module's alone (a body
// without plasticity or conduction): it starts at the body's temperature, as there.
template <int D>
void RigidSurfaceModule<D>::on_create(Simulation<D>& sim) {
  if (kT_ < 0) return;
  auto& p = sim.particles();
  auto T = p.template view<double>(kT_);
  auto bd = p.body();
  for (std::size_t i = 0; i < p.size(); ++i) {
    const BodyInfo& b = sim.bodies()[bd[i]];
    T[i] = sim.materials()[b.material].initial_temperature(b.temperature);
  }
}

template <int D>
int RigidSurfaceModule<D>::find(const std::string& name) const {
  for (std::size_t k = 0; k < s_.size(); ++k)
    if (s_[k].name == name) return static_cast<int>(k);
  return -1;
}

template <int D>
Vec<D> RigidSurfaceModule<D>::velocity_at(const Surface& s, double t) const {
  if (s.velocity_expr.empty()) return s.v0;
  Vec<D> v;
  for (int a = 0; a < D; ++a) v[a] = s.velocity_expr[a](0.0, 0.0, 0.0, t);
  return v;
}

template <int D>
void RigidSurfaceModule<D>::sync(double t) {
  // The displacement is state that checkpoints do not hold: after a restart it is integrated
  // again from t = 0 (exact for a constant velocity, composite Simpson otherwise).
  if (t == t_) return;
  for (auto& s : s_) {
    if (s.constant) {
      s.displacement = s.v0 * t;
      continue;
    }
    const int n = 20000;
    const double h = t / n;
    Vec<D> sum = Vec<D>::Zero();
    for (int k = 0; k < n; ++k)
      sum +=
          velocity_at(s, k * h) + 4 * velocity_at(s, (k + 0.5) * h) + velocity_at(s, (k + 1) * h);
    s.displacement = sum * (h / 6);
  }
  t_ = t;
}

template <int D>
void RigidSurfaceModule<D>::drift(Simulation<D>& sim, double dt) {
  // Called before the simulation time moves to t + dt: the surfaces move with it, so that the
  // force pass sees them at t + dt (kick-drift-kick). Simpson's rule over the step: exact for a
  // velocity that is at most cubic in t.
  const double t = sim.time();
  sync(t);
  for (auto& s : s_) {
    if (s.constant) {
      s.displacement = s.v0 * (t + dt);
    } else {
      s.displacement += (dt / 6) * (velocity_at(s, t) + 4 * velocity_at(s, t + 0.5 * dt) +
                                    velocity_at(s, t + dt));
    }
  }
  t_ = t + dt;
  if (kq_ < 0) return;
  // Friction heat of the last force pass, explicit as conduction (src/heat).
  auto& p = sim.particles();
  auto T = p.template view<double>(kT_);
  auto q = p.template view<double>(kq_);
  const std::size_t n = p.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) T[i] += dt * q[i];
}

template <int D>
void RigidSurfaceModule<D>::forces(Simulation<D>& sim) {
  sync(sim.time());
  auto& p = sim.particles();
  auto x = p.x();
  auto v = p.v();
  auto a = p.a();
  auto m = p.m();
  auto ph = p.phase();
  auto mt = p.material();
  const std::size_t n = p.size(), own = sim.owned();
  const int ns = static_cast<int>(s_.size());
  const double R = radius_, depth = depth_, dt = sim.dt();
  // The per-particle contact stiffness entering max_dt is taken at an overlap of at least 0.1 R,
  // so that a particle arriving at a surface does not meet a step chosen for no contact.
  const double delta_floor = 0.1 * R;
  std::vector<double> e_max(sim.materials().size(), 0.0);
  for (auto& s : s_) {
    s.velocity = velocity_at(s, sim.time());
    s.force.resize(n);
    for (std::size_t k = 0; k < e_max.size(); ++k) e_max[k] = std::max(e_max[k], s.e_star[k]);
  }
  std::span<double> q, T;
  if (kq_ >= 0) q = p.template view<double>(kq_), T = p.template view<double>(kT_);
  double w2 = 0;
#pragma omp parallel for schedule(static) reduction(max : w2)
  for (std::size_t i = 0; i < n; ++i) {
    if (ph[i] != kSolid && ph[i] != kFluid) {
      for (int k = 0; k < ns; ++k) s_[k].force[i].setZero();
      if (kq_ >= 0) q[i] = 0;
      continue;
    }
    double delta_max = delta_floor;
    double heating = 0;  // friction and surface heat into the particle, W (per metre in 2D)
    Vec<D> sum = Vec<D>::Zero();
    for (int k = 0; k < ns; ++k) {
      Surface& s = s_[k];
      Vec<D>& f = s.force[i];
      f.setZero();
      // In the surface's frame: the closest point of all its elements (one contact per surface).
      const Vec<D> xl = x[i] - s.displacement;
      Vec<D> c;
      int e;
      if (!s.geometry.closest(xl, R, c, e)) continue;
      double power = 0;
      f = contact_force<D>(xl, v[i], m[i], c, s.geometry.elements()[e].normal, s.velocity, R,
                           s.e_star[mt[i]], s.friction, dt, depth, nullptr, s.damping,
                           s.friction_cap, &power);
      heating += (1 - s.heat_partition) * power;
      if (s.conductance > 0) heating += s.conductance * (s.temperature - T[i]);
      delta_max = std::max(delta_max, R - (xl - c).norm());
      sum += f;
    }
    a[i] += sum / m[i];
    // dT/dt = ((1 - beta) P + h_c dp^(D-1) (T_s - T)) / (m C_p); no heat capacity: no heating
    if (kq_ >= 0) {
      const double cp = sim.materials()[mt[i]].heat_capacity;
      q[i] = cp > 0 ? heating / (m[i] * cp) : 0.0;
    }
    if (i >= own) continue;  // ghost: its owner counts it
    // Contact frequency squared k/m with k = dF/d(delta) = 2 E* sqrt(R delta) (per depth in 2D).
    w2 = std::max(w2, hertz_stiffness(e_max[mt[i]], R, delta_max) / depth / m[i]);
  }
  const Comm& comm = sim.comm();
  omega2_ = comm.max(w2);
  // Reactions: serial sums in particle order (the same for any thread count), over the owned
  // particles and then the ranks.
  for (auto& s : s_) {
    s.reaction.setZero();
    s.contacts = 0;
    for (std::size_t i = 0; i < own; ++i) {
      if (s.force[i].squaredNorm() > 0) ++s.contacts;
      s.reaction -= s.force[i];
    }
    comm.sum(std::span<double>(s.reaction.data(), D));
    s.contacts = comm.sum(static_cast<long>(s.contacts));
  }
}

template <int D>
double RigidSurfaceModule<D>::potential_energy(Simulation<D>& sim) {
  // The contacts of forces() at the current positions: the closest point of each surface within
  // R; serial over the owned particles (the same for any thread count).
  sync(sim.time());
  auto& p = sim.particles();
  auto x = p.x();
  auto ph = p.phase();
  auto mt = p.material();
  double e = 0;
  for (std::size_t i = 0; i < sim.owned(); ++i) {
    if (ph[i] != kSolid && ph[i] != kFluid) continue;
    for (const Surface& s : s_) {
      const Vec<D> xl = x[i] - s.displacement;
      Vec<D> c;
      int el;
      if (!s.geometry.closest(xl, radius_, c, el)) continue;
      e += hertz_energy(s.e_star[mt[i]], radius_, radius_ - (xl - c).norm()) / depth_;
    }
  }
  return e;
}

template <int D>
double RigidSurfaceModule<D>::max_dt(Simulation<D>&) {
  // A Hertz contact is a spring of frequency sqrt(k/m): dt <= 0.1 pi sqrt(m/k), 20 steps per
  // period (../shared/reference/equations.md Sect. 7), with k at the largest overlap (>= 0.1 R).
  if (!(omega2_ > 0)) return std::numeric_limits<double>::infinity();
  return 0.1 * std::numbers::pi / std::sqrt(omega2_);
}

template <int D>
std::vector<std::string> RigidSurfaceModule<D>::probe_columns(const ProbeSpec& spec) const {
  if (find(spec.body) < 0) return {};
  if (spec.type == "surface_force" || spec.type == "surface_displacement") {
    std::vector<std::string> c;
    for (int a = 0; a < D; ++a) c.push_back(std::string("_") + "xyz"[a]);
    return c;
  }
  if (spec.type == "surface_contacts" || spec.type == "chip_ratio") return {""};
  return {};
}

template <int D>
double RigidSurfaceModule<D>::chip_ratio(Simulation<D>& sim, const ProbeSpec& spec) const {
  // The chip in the window (scene/scene_probes.cpp, read_chip): the particles of the body at
  // distances s in `range` up the rake face and d in [-dp, 5 size] along its normal, binned dp/2
  // wide in d (extent and summed velocity relative to the surface per bin).
  const Surface& s = s_[find(spec.body)];
  auto& p = sim.particles();
  auto x = p.x();
  auto v = p.v();
  auto m = p.m();
  auto rho = p.rho();
  auto bd = p.body();
  int body = -1;
  for (std::size_t b = 0; b < sim.bodies().size(); ++b)
    if (sim.bodies()[b].name == spec.target) body = static_cast<int>(b);
  Vec<D> p0, axis, normal;
  for (int a = 0; a < D; ++a)
    p0[a] = spec.point[a], axis[a] = spec.axis[a], normal[a] = spec.normal[a];
  p0 += s.displacement;
  const double dp = sim.scene().dp, d0 = -dp, d1 = 5 * spec.size, w = 0.5 * dp;
  const std::size_t nb = static_cast<std::size_t>(std::ceil((d1 - d0) / w));
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> lo(nb, inf), hi(nb, -inf), vel(nb * D, 0.0);
  double sum[2] = {0, 0};  // flow: volume and volume x speed relative to the surface
  for (std::size_t i = 0; i < sim.owned(); ++i) {
    if (bd[i] != body) continue;
    const Vec<D> r = x[i] - p0, vr = v[i] - s.velocity;
    const double along = r.dot(axis), d = r.dot(normal);
    if (along < spec.range[0] || along > spec.range[1] || d < d0 || d >= d1) continue;
    const double vol = m[i] / rho[i];
    sum[0] += vol, sum[1] += vol * vr.norm();
    const std::size_t k = std::min(nb - 1, static_cast<std::size_t>((d - d0) / w));
    lo[k] = std::min(lo[k], d), hi[k] = std::max(hi[k], d);
    for (int a = 0; a < D; ++a) vel[k * D + a] += vol * vr[a];
  }
  const Comm& comm = sim.comm();
  if (spec.method == "flow") {
    // Steady chip, mass conservation: rho vc h = rho v_chip t_c, so t_c / h = vc / v_chip with
    // v_chip the mean speed over the chip's section (a curled chip turning rigidly too).
    comm.sum(std::span<double>(sum));
    return sum[1] > 0 ? s.velocity.norm() * sum[0] / sum[1] : 0.0;
  }
  comm.min(std::span<double>(lo)), comm.max(std::span<double>(hi));
  comm.sum(std::span<double>(vel));
  // Runs of occupied bins without a gap wider than 1.5 dp. layer: the run from the nearest
  // particle (a curled-back part further out is not the layer), thickness max d - min d + dp.
  // section: the widest run, e the direction of its mean velocity relative to the surface: the
  // thickness normal to the flow of a chip crossing the window.
  const bool section = spec.method == "section";
  double first = inf, last = -inf, best = 0, best_first = 0, best_last = 0;
  Vec<D> flow = Vec<D>::Zero(), best_flow = Vec<D>::Zero();
  for (std::size_t k = 0; k <= nb; ++k) {
    const bool occupied = k < nb && hi[k] >= lo[k];
    if (occupied && first < inf && lo[k] - last <= 1.5 * dp) {
      last = hi[k];
    } else if (occupied || k == nb) {
      if (first < inf && last - first + dp > best)
        best = last - first + dp, best_flow = flow, best_first = first, best_last = last;
      if (first < inf && !section) break;  // layer: the first run only
      if (k == nb) break;
      first = lo[k], last = hi[k], flow.setZero();
    } else {
      continue;
    }
    for (int a = 0; a < D; ++a) flow[a] += vel[k * D + a];
  }
  if (!section) return best / spec.size;
  // A strip of thickness t flowing along e: its particles at the least and the greatest d lie
  // at s_first and s_last along the axis, d_last - d_first + dp = (t + (s_last - s_first)
  // (e.normal)) / (e.axis), so t = |extent (e.axis) - (s_last - s_first) (e.normal)| (the
  // positions along the axis from a second pass: the extremes may be on other ranks).
  const double f = best_flow.norm();
  if (!(f > 0)) return 0.0;
  double at[4] = {0, 0, 0, 0};  // sum and count of s at d = first, at d = last
  for (std::size_t i = 0; i < sim.owned(); ++i) {
    if (bd[i] != body) continue;
    const Vec<D> r = x[i] - p0;
    const double along = r.dot(axis), d = r.dot(normal);
    if (along < spec.range[0] || along > spec.range[1]) continue;
    if (d == best_first) at[0] += along, at[1] += 1;
    if (d == best_last) at[2] += along, at[3] += 1;
  }
  comm.sum(std::span<double>(at));
  const Vec<D> e = best_flow / f;
  const double ds = at[1] > 0 && at[3] > 0 ? at[2] / at[3] - at[0] / at[1] : 0.0;
  return std::abs(best * e.dot(axis) - ds * e.dot(normal)) / spec.size;
}

template <int D>
void RigidSurfaceModule<D>::probe(Simulation<D>& sim, const ProbeSpec& spec,
                                  std::vector<double>& out) {
  const Surface& s = s_[find(spec.body)];
  sync(sim.time());
  if (spec.type == "chip_ratio")
    out.push_back(chip_ratio(sim, spec));
  else if (spec.type == "surface_force")
    for (int a = 0; a < D; ++a) out.push_back(s.reaction[a]);
  else if (spec.type == "surface_displacement")
    for (int a = 0; a < D; ++a) out.push_back(s.displacement[a]);
  else
    out.push_back(s.contacts);
}

template class RigidSurfaceModule<2>;
template class RigidSurfaceModule<3>;

}  // namespace monosph
