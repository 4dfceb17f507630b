#include "cluster_module.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "rigid/cluster_keys.hpp"

namespace monosph {

namespace {

Vec3 cross(const Vec3& a, const Vec3& b) {
  return a.cross(b);
}

}  // namespace

template <int D>
ClusterModule<D>::ClusterModule(Simulation<D>& sim) {
  auto& p = sim.particles();
  kcl_ = p.add_field("cluster", 1, FieldType::Int, true);  // cluster index, -1 for others
  koff_ = p.add_field("cluster_offset", D);  // body-frame position from the cluster centre
  // grad v of the rigid motion, skew(omega), read by the fluid's wall condition (zero elsewhere)
  kG_ = p.add_field("rigid_velocity_gradient", D * D);
  const Scene& s = sim.scene();
  for (const auto& b : sim.bodies()) body_names_.push_back(b.name);
  for (int a = 0; a < D; ++a) {
    lo_[a] = s.domain_min[a];
    len_[a] = s.domain_max[a] - s.domain_min[a];
    periodic_[a] = s.periodic[a];
  }
}

template <int D>
Vec<D> ClusterModule<D>::min_image(Vec<D> d) const {
  for (int a = 0; a < D; ++a)
    if (periodic_[a]) d[a] -= len_[a] * std::round(d[a] / len_[a]);
  return d;
}

template <int D>
Mat<D> ClusterModule<D>::rotation(const Cluster& c) const {
  if constexpr (D == 2) {
    const double co = std::cos(c.angle), si = std::sin(c.angle);
    Mat<D> r;
    r << co, -si, si, co;
    return r;
  } else {
    return Mat<D>(c.q.toRotationMatrix());
  }
}

template <int D>
Vec3 ClusterModule<D>::world_omega(const Cluster& c) const {
  if constexpr (D == 2) {
    return c.omega;
  } else {
    const Mat3 r = c.q.toRotationMatrix();
    return Vec3(r * (c.inertia_body_inv * (r.transpose() * c.momentum)));  // I_w^-1 L
  }
}

template <int D>
Vec3 ClusterModule<D>::angular_momentum(const Cluster& c) const {
  if constexpr (D == 2)
    return Vec3(0, 0, c.inertia * c.omega[2]);
  else
    return c.momentum;
}

template <int D>
void ClusterModule<D>::collect_members(Simulation<D>& sim) {
  auto& p = sim.particles();
  auto cl = p.template view<std::int64_t>(kcl_);
  for (auto& c : c_) c.members.clear();
  for (std::size_t i = 0; i < p.size(); ++i)
    if (cl[i] >= 0) c_[cl[i]].members.push_back(i);
}

template <int D>
void ClusterModule<D>::mass_properties(Simulation<D>& sim) {
  // Each member is a square (cube) of side dp: its own inertia m dp^2/6 about every axis is added
  // to the point-mass sum, so that a lattice-filled grain has the inertia of its filled cells.
  // Sums over the members of every rank (MPI).
  auto& p = sim.particles();
  auto m = p.m();
  auto off = p.template view<Vec<D>>(koff_);
  const double own = sim.dp() * sim.dp() / 6.0;
  std::vector<double> s(11 * c_.size(), 0.0);
  for (std::size_t c = 0; c < c_.size(); ++c) {
    Mat3 ib = Mat3::Zero();
    double mass = 0, inertia = 0;
    for (std::size_t k : c_[c].members) {
      mass += m[k];
      const Vec3 b = pad3<D>(off[k]);
      inertia += m[k] * (b.squaredNorm() + own);
      ib += m[k] * ((b.squaredNorm() + own) * Mat3::Identity() - b * b.transpose());
    }
    s[11 * c] = mass, s[11 * c + 1] = inertia;
    for (int q = 0; q < 9; ++q) s[11 * c + 2 + q] = ib(q);
  }
  sim.comm().sum_same(s);
  for (std::size_t c = 0; c < c_.size(); ++c) {
    auto& cc = c_[c];
    cc.mass = s[11 * c], cc.inertia = s[11 * c + 1];
    for (int q = 0; q < 9; ++q) cc.inertia_body(q) = s[11 * c + 2 + q];
    if constexpr (D == 3) cc.inertia_body_inv = cc.inertia_body.inverse();
  }
}

template <int D>
void ClusterModule<D>::set_members(Simulation<D>& sim, bool positions) {
  auto& p = sim.particles();
  auto x = p.x();
  auto v = p.v();
  auto off = p.template view<Vec<D>>(koff_);
  auto G = p.template view<Mat<D>>(kG_);
  // One cluster per iteration: the members of a cluster are disjoint from the others'.
#pragma omp parallel for schedule(dynamic, 1)
  for (std::size_t q = 0; q < c_.size(); ++q) {
    const Cluster& c = c_[q];
    const Mat<D> rot = rotation(c);
    const Vec3 w = world_omega(c);
    Mat3 skew;
    skew << 0, -w[2], w[1], w[2], 0, -w[0], -w[1], w[0], 0;
    for (std::size_t k : c.members) {
      G[k] = skew.template topLeftCorner<D, D>();
      const Vec<D> r = rot * off[k];
      v[k] = c.velocity + cross(w, pad3<D>(r)).template head<D>();
      if (!positions) continue;
      // x = X + R b, as the periodic image nearest to where the particle is (the neighbour list
      // expects continuous positions between rebuilds).
      Vec<D> xn = c.centre + r;
      for (int a = 0; a < D; ++a)
        if (periodic_[a]) xn[a] += len_[a] * std::round((x[k][a] - xn[a]) / len_[a]);
      x[k] = xn;
    }
  }
}

template <int D>
void ClusterModule<D>::on_create(Simulation<D>& sim) {
  // MPI: each rank holds some members of a cluster; every sum below is reduced over the ranks,
  // so that all ranks hold the same cluster state (and integrate it alike).
  auto& p = sim.particles();
  auto x = p.x();
  auto v = p.v();
  auto m = p.m();
  auto bd = p.body();
  auto ids = p.id();
  auto cl = p.template view<std::int64_t>(kcl_);
  auto off = p.template view<Vec<D>>(koff_);
  const Scene& scene = sim.scene();
  const Comm& comm = sim.comm();
  c_.clear();
  for (std::size_t i = 0; i < p.size(); ++i) cl[i] = -1;
  std::string err;
  for (std::size_t b = 0; b < sim.bodies().size(); ++b) {
    if (sim.bodies()[b].phase != kRigid) continue;
    const BodySpec& spec = scene.bodies[b];
    const bool per_part = module_params<ClusterBodyKeys>(spec.params).per_part;
    const std::size_t nparts = per_part ? spec.shape.parts.size() : 1;
    std::vector<double> count(nparts, 0.0);
    std::vector<std::size_t> part_of(p.size(), 0);
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (bd[i] != static_cast<std::int64_t>(b)) continue;
      std::size_t part = 0;
      if (per_part) {
        Point xi(x[i].data(), x[i].data() + D);
        if (spec.rotate) xi = spec.rotate->apply(xi, true);  // where the fill found it
        while (part < nparts && !spec.shape.parts[part].contains(xi)) ++part;
        if (part == nparts) {
          err = "bodies[" + std::to_string(b) + "] (" + spec.name +
                ").clusters: a particle lies in no part (jitter moved it out)";
          part = 0;
        }
      }
      part_of[i] = part;
      count[part] += 1;
    }
    comm.sum(count);
    // One cluster per part that holds particles, numbered in part order.
    std::vector<long> id(nparts, -1);
    const std::size_t first = c_.size();
    for (std::size_t q = 0; q < nparts; ++q) {
      if (count[q] == 0) continue;
      id[q] = static_cast<long>(c_.size());
      c_.emplace_back();
      c_.back().body = static_cast<int>(b);
    }
    for (std::size_t i = 0; i < p.size(); ++i)
      if (bd[i] == static_cast<std::int64_t>(b)) cl[i] = id[part_of[i]];
    for (std::size_t c = first; c < c_.size(); ++c) {
      if (spec.angular_velocity.empty()) continue;
      if constexpr (D == 2)
        c_[c].omega = Vec3(0, 0, spec.angular_velocity[0]);
      else
        c_[c].omega =
            Vec3(spec.angular_velocity[0], spec.angular_velocity[1], spec.angular_velocity[2]);
    }
  }
  err = comm.first_message(err);
  if (!err.empty()) throw InputError(err);
  collect_members(sim);
  const std::size_t nc = c_.size();
  // Centre from positions unwrapped around the member with the lowest id (a cluster may straddle
  // a periodic boundary); offsets in the body frame (identity rotation at t = 0).
  std::vector<double> first_id(nc, 1e300);
  for (std::size_t c = 0; c < nc; ++c)
    for (std::size_t k : c_[c].members) first_id[c] = std::min(first_id[c], double(ids[k]));
  comm.min(first_id);
  std::vector<double> ref(nc * D, 0.0), sums(nc * (2 * D + 1), 0.0);
  for (std::size_t c = 0; c < nc; ++c)
    for (std::size_t k : c_[c].members)
      if (double(ids[k]) == first_id[c])
        for (int a = 0; a < D; ++a) ref[c * D + a] = x[k][a];
  comm.sum_same(ref);  // one rank holds that member
  for (std::size_t c = 0; c < nc; ++c) {
    const Vec<D> x0 = Eigen::Map<const Vec<D>>(&ref[c * D]);
    double* sm = &sums[c * (2 * D + 1)];
    for (std::size_t k : c_[c].members) {
      const Vec<D> xu = x0 + min_image(x[k] - x0);
      for (int a = 0; a < D; ++a) sm[a] += m[k] * xu[a], sm[D + a] += m[k] * v[k][a];
      sm[2 * D] += m[k];
    }
  }
  comm.sum_same(sums);
  for (std::size_t c = 0; c < nc; ++c) {
    auto& cc = c_[c];
    const double* sm = &sums[c * (2 * D + 1)];
    const Vec<D> x0 = Eigen::Map<const Vec<D>>(&ref[c * D]);
    for (int a = 0; a < D; ++a)
      cc.centre[a] = sm[a] / sm[2 * D], cc.velocity[a] = sm[D + a] / sm[2 * D];
    for (std::size_t k : cc.members) off[k] = x0 + min_image(x[k] - x0) - cc.centre;
  }
  mass_properties(sim);
  // The rigid projection of the initial velocity field: linear momentum (above) and angular
  // momentum sum_k m_k r_k x v_k about the centre, plus the given angular_velocity. A grain
  // started in a shear flow u(y) thus spins at about -u'/2, as the fluid around it.
  std::vector<double> ls(3 * nc, 0.0);
  for (std::size_t c = 0; c < nc; ++c) {
    Vec3 l = Vec3::Zero();
    for (std::size_t k : c_[c].members)
      l += pad3<D>(off[k]).cross(pad3<D>(Vec<D>(m[k] * (v[k] - c_[c].velocity))));
    for (int a = 0; a < 3; ++a) ls[3 * c + a] = l[a];
  }
  comm.sum_same(ls);
  for (std::size_t c = 0; c < nc; ++c) {
    auto& cc = c_[c];
    const Vec3 l(ls[3 * c], ls[3 * c + 1], ls[3 * c + 2]);
    if constexpr (D == 2)
      cc.omega[2] += l[2] / cc.inertia;
    else
      cc.momentum = l + cc.inertia_body * cc.omega;  // q = identity
  }
  set_members(sim, false);
}

template <int D>
void ClusterModule<D>::on_rebuild(Simulation<D>& sim) {
  collect_members(sim);  // the particles may have been re-ordered
}

template <int D>
void ClusterModule<D>::forces(Simulation<D>& sim) {
  // F = sum_k m_k a_k and T = sum_k r_k x m_k a_k over everything the members received (Eq. in
  // equations.md Sect. 5); each cluster's sums in member order (the same for any thread count).
  // Then the members get the rigid acceleration a_k = A + alpha x r_k + omega x (omega x r_k),
  // which the fluid's wall condition reads in the next step.
  auto& p = sim.particles();
  auto a = p.a();
  auto m = p.m();
  auto off = p.template view<Vec<D>>(koff_);
  const std::size_t own = sim.owned();  // members on other ranks add there (MPI)
#pragma omp parallel for schedule(dynamic, 1)
  for (std::size_t q = 0; q < c_.size(); ++q) {
    Cluster& c = c_[q];
    const Mat<D> rot = rotation(c);
    c.force.setZero();
    c.torque.setZero();
    for (std::size_t k : c.members) {
      if (k >= own) continue;
      const Vec<D> f = m[k] * a[k];
      c.force += f;
      c.torque += cross(pad3<D>(Vec<D>(rot * off[k])), pad3<D>(f));
    }
  }
  if (sim.comm().parallel()) {  // one reduction for all clusters; every rank integrates alike
    // (from the same bits: rank 0's sums are broadcast)
    auto& ft = reduce_buf_;  // kept between steps: no allocation
    ft.clear();
    for (const auto& c : c_) {
      for (int a = 0; a < D; ++a) ft.push_back(c.force[a]);
      for (int a = 0; a < 3; ++a) ft.push_back(c.torque[a]);
    }
    sim.comm().sum_same(ft);
    std::size_t q = 0;
    for (auto& c : c_) {
      for (int a = 0; a < D; ++a) c.force[a] = ft[q++];
      for (int a = 0; a < 3; ++a) c.torque[a] = ft[q++];
    }
  }
#pragma omp parallel for schedule(dynamic, 1)
  for (std::size_t q = 0; q < c_.size(); ++q) {
    const Cluster& c = c_[q];
    const Mat<D> rot = rotation(c);
    const Vec<D> acc = c.force / c.mass;
    const Vec3 w = world_omega(c);
    Vec3 alpha;
    if constexpr (D == 2) {
      alpha = Vec3(0, 0, c.torque[2] / c.inertia);
    } else {
      // Euler's equations in the world frame: I_w omega' = T - omega x L.
      const Mat3 r = c.q.toRotationMatrix();
      const Mat3 iw_inv = r * c.inertia_body_inv * r.transpose();
      alpha = iw_inv * (c.torque - w.cross(c.momentum));
    }
    for (std::size_t k : c.members) {
      const Vec3 r = pad3<D>(Vec<D>(rot * off[k]));
      a[k] = acc + (cross(alpha, r) + cross(w, cross(w, r))).template head<D>();
    }
  }
}

template <int D>
void ClusterModule<D>::kicked(Simulation<D>& sim, double h) {
  for (auto& c : c_) {
    c.velocity += h * c.force / c.mass;
    if constexpr (D == 2)
      c.omega[2] += h * c.torque[2] / c.inertia;
    else
      c.momentum += h * c.torque;  // L^{n+1/2} = L^n + h T (equations.md Sect. 5)
  }
  set_members(sim, false);
}

template <int D>
void ClusterModule<D>::drift(Simulation<D>& sim, double dt) {
  for (auto& c : c_) {
    c.centre += dt * c.velocity;
    for (int a = 0; a < D; ++a)  // keep the centre in the periodic box
      if (periodic_[a]) c.centre[a] -= len_[a] * std::floor((c.centre[a] - lo_[a]) / len_[a]);
    if constexpr (D == 2) {
      c.angle += dt * c.omega[2];
    } else {
      // q^{n+1} = [cos(|w| dt/2), sin(|w| dt/2) w/|w|] q^n with w = I_w^-1 L^{n+1/2} taken at
      // the orientation half-way through the step (a predictor), which makes the rotation
      // second-order accurate: w evaluated at q^n alone lets the energy of a free asymmetric top
      // drift by O(dt).
      auto turn = [](const Eigen::Quaterniond& q, const Vec3& w, double t) {
        const double wn = w.norm();
        if (!(wn > 0)) return q;
        return Eigen::Quaterniond(Eigen::AngleAxisd(wn * t, w / wn) * q).normalized();
      };
      Cluster half = c;
      half.q = turn(c.q, world_omega(c), 0.5 * dt);
      c.q = turn(c.q, world_omega(half), dt);
    }
  }
  set_members(sim, true);
}

template <int D>
double ClusterModule<D>::max_dt(Simulation<D>&) {
  // At most 0.01 rad of rotation per step (equations.md Sect. 5).
  double w = 0;
  for (const auto& c : c_) w = std::max(w, world_omega(c).norm());
  return w > 0 ? 0.01 / w : std::numeric_limits<double>::infinity();
}

template <int D>
void ClusterModule<D>::save_state(std::map<std::string, double>& s) const {
  s["clusters.count"] = static_cast<double>(c_.size());
  for (std::size_t k = 0; k < c_.size(); ++k) {
    const Cluster& c = c_[k];
    auto put = [&](const char* what, int comp, double v) {
      s[fmt::format("clusters.{}.{}.{}", k, what, comp)] = v;
    };
    for (int a = 0; a < D; ++a) {
      put("centre", a, c.centre[a]);
      put("velocity", a, c.velocity[a]);
      put("force", a, c.force[a]);
    }
    for (int a = 0; a < 3; ++a) {
      put("torque", a, c.torque[a]);
      put("omega", a, c.omega[a]);
      put("momentum", a, c.momentum[a]);
    }
    put("angle", 0, c.angle);
    // Mass and inertia as computed at the start: summed again in another particle order they
    // would differ in the last bits and a restart would not be bit-identical.
    put("mass", 0, c.mass);
    put("inertia", 0, c.inertia);
    for (int a = 0; a < 9; ++a) put("inertia_body", a, c.inertia_body(a / 3, a % 3));
    put("q", 0, c.q.w()), put("q", 1, c.q.x()), put("q", 2, c.q.y()), put("q", 3, c.q.z());
  }
}

template <int D>
void ClusterModule<D>::load_state(Simulation<D>& sim, const std::map<std::string, double>& s) {
  auto& p = sim.particles();
  auto cl = p.template view<std::int64_t>(kcl_);
  auto bd = p.body();
  auto it = s.find("clusters.count");
  if (it == s.end()) throw InputError("checkpoint: no rigid-cluster state (clusters.count)");
  c_.assign(static_cast<std::size_t>(it->second), Cluster{});
  for (std::size_t i = 0; i < p.size(); ++i)
    if (cl[i] >= 0) c_.at(cl[i]).body = static_cast<int>(bd[i]);
  collect_members(sim);
  for (std::size_t k = 0; k < c_.size(); ++k) {
    Cluster& c = c_[k];
    auto get = [&](const char* what, int comp) {
      auto f = s.find(fmt::format("clusters.{}.{}.{}", k, what, comp));
      if (f == s.end()) throw InputError(fmt::format("checkpoint: no state of cluster {}", k));
      return f->second;
    };
    for (int a = 0; a < D; ++a) {
      c.centre[a] = get("centre", a);
      c.velocity[a] = get("velocity", a);
      c.force[a] = get("force", a);
    }
    for (int a = 0; a < 3; ++a) {
      c.torque[a] = get("torque", a);
      c.omega[a] = get("omega", a);
      c.momentum[a] = get("momentum", a);
    }
    c.angle = get("angle", 0);
    c.mass = get("mass", 0);
    c.inertia = get("inertia", 0);
    for (int a = 0; a < 9; ++a) c.inertia_body(a / 3, a % 3) = get("inertia_body", a);
    c.inertia_body_inv = c.inertia_body.inverse();
    c.q = Eigen::Quaterniond(get("q", 0), get("q", 1), get("q", 2), get("q", 3));
  }
}

template class ClusterModule<2>;
template class ClusterModule<3>;

}  // namespace monosph
