// Probes of rigid bodies: centre of mass, velocity and angular velocity (ClusterModule).
#include <algorithm>
#include <cmath>
#include <limits>

#include "cluster_module.hpp"

namespace monosph {

template <int D>
std::vector<std::string> ClusterModule<D>::probe_columns(const ProbeSpec& s) const {
  const bool vector = s.type == "rigid_centre" || s.type == "rigid_velocity";
  if (!vector && s.type != "rigid_angular_velocity") return {};
  if (std::find(body_names_.begin(), body_names_.end(), s.body) == body_names_.end()) return {};
  if (!vector && D == 2) return {""};
  std::vector<std::string> c;
  for (int a = 0; a < (vector ? D : 3); ++a) c.push_back(std::string("_") + "xyz"[a]);
  return c;
}

template <int D>
void ClusterModule<D>::probe(Simulation<D>&, const ProbeSpec& s, std::vector<double>& out) {
  // Every rank holds the same cluster state: no reduction needed.
  const auto b = std::find(body_names_.begin(), body_names_.end(), s.body) - body_names_.begin();
  const BodyMotion m = body_motion(static_cast<int>(b));
  if (s.type == "rigid_centre")
    for (int a = 0; a < D; ++a) out.push_back(m.centre[a]);
  else if (s.type == "rigid_velocity")
    for (int a = 0; a < D; ++a) out.push_back(m.velocity[a]);
  else if (D == 2)
    out.push_back(m.omega[2]);
  else
    for (int a = 0; a < 3; ++a) out.push_back(m.omega[a]);
}

template <int D>
typename ClusterModule<D>::BodyMotion ClusterModule<D>::body_motion(int body) const {
  std::vector<const Cluster*> cs;
  for (const auto& c : c_)
    if (c.body == body) cs.push_back(&c);
  BodyMotion m;
  if (cs.empty()) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    m.centre.setConstant(nan), m.velocity.setConstant(nan), m.omega.setConstant(nan);
    return m;
  }
  if (cs.size() == 1) {
    m.centre = cs[0]->centre, m.velocity = cs[0]->velocity, m.omega = world_omega(*cs[0]);
    return m;
  }
  // Several clusters (clusters: per_part): mass-weighted centre (the centres unwrapped about the
  // first cluster's, then put back into the periodic box) and velocity; omega = I^-1 L with L
  // and I of all clusters about that centre (parallel-axis terms m d x (V_c - V), m |d|^2).
  const Vec<D> x0 = cs[0]->centre;
  double mass = 0;
  for (const Cluster* c : cs) {
    mass += c->mass;
    m.centre += c->mass * (x0 + min_image(c->centre - x0));
    m.velocity += c->mass * c->velocity;
  }
  m.centre /= mass, m.velocity /= mass;
  Vec3 l = Vec3::Zero();
  Mat3 inertia = Mat3::Zero();
  for (const Cluster* c : cs) {
    const Vec3 d = pad3<D>(Vec<D>(x0 + min_image(c->centre - x0) - m.centre));
    l += angular_momentum(*c) + c->mass * d.cross(pad3<D>(Vec<D>(c->velocity - m.velocity)));
    Mat3 own = Mat3::Identity() * c->inertia;  // 2D: polar inertia (only (2, 2) is used)
    if constexpr (D == 3) {
      const Mat3 r = c->q.toRotationMatrix();
      own = r * c->inertia_body * r.transpose();
    }
    inertia += own + c->mass * (d.squaredNorm() * Mat3::Identity() - d * d.transpose());
  }
  if constexpr (D == 2)
    m.omega = Vec3(0, 0, l[2] / inertia(2, 2));
  else
    m.omega = inertia.inverse() * l;
  for (int a = 0; a < D; ++a)  // the centre in the periodic box, as a cluster's
    if (periodic_[a]) m.centre[a] -= len_[a] * std::floor((m.centre[a] - lo_[a]) / len_[a]);
  return m;
}

// The class itself is instantiated in cluster_module.cpp; these members here.
#define MONOSPH_CLUSTER_PROBES(D)                                                                \
  template std::vector<std::string> ClusterModule<D>::probe_columns(const ProbeSpec&) const;     \
  template void ClusterModule<D>::probe(Simulation<D>&, const ProbeSpec&, std::vector<double>&); \
  template ClusterModule<D>::BodyMotion ClusterModule<D>::body_motion(int) const;
MONOSPH_CLUSTER_PROBES(2)
MONOSPH_CLUSTER_PROBES(3)
#undef MONOSPH_CLUSTER_PROBES

}  // namespace monosph
