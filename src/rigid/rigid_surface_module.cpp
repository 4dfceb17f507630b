#include "rigid_surface_module.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "chip_probe.hpp"
#include "core/initial_temperature.hpp"

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
  if (kT_ >= 0) set_initial_temperatures(sim, kT_);
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
void RigidSurfaceModule<D>::probe(Simulation<D>& sim, const ProbeSpec& spec,
                                  std::vector<double>& out) {
  const Surface& s = s_[find(spec.body)];
  sync(sim.time());
  if (spec.type == "chip_ratio")
    out.push_back(chip_ratio(sim, spec, s.displacement, s.velocity));
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
