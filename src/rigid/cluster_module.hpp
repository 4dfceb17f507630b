#pragma once
// Rigid clusters (abrasive grains; Mohseni-Mofidi & Bierwisch 2020 Sect. 3.6 after Polfer, Kraft &
// Bierwisch 2016; ../shared/reference/equations.md Sect. 5). The particles of a rigid body (or
// of each part of its union shape) form one cluster: mass, centre of mass and inertia from its
// particles; force and torque from everything its particles feel (fluid through the Adami
// condition, contact, body force); translation and rotation integrated kick-drift-kick (angle in
// 2D, quaternion and world angular momentum in 3D); member positions, velocities and
// accelerations are set rigidly from the cluster, never integrated per member. The centre is
// kept unwrapped, so a cluster split by a periodic boundary stays whole.
#include <Eigen/Geometry>
#include <vector>

#include "core/simulation.hpp"

namespace monosph {

template <int D>
class ClusterModule : public Module<D> {
 public:
  explicit ClusterModule(Simulation<D>& sim);
  std::string name() const override { return "clusters"; }
  void on_create(Simulation<D>& sim) override;
  void on_rebuild(Simulation<D>& sim) override;
  void forces(Simulation<D>& sim) override;
  void kicked(Simulation<D>& sim, double h) override;
  void drift(Simulation<D>& sim, double dt) override;
  double max_dt(Simulation<D>& sim) override;
  bool reads_pair_rows(int) const override { return false; }  // no pair passes
  void save_state(std::map<std::string, double>& s) const override;
  void load_state(Simulation<D>& sim, const std::map<std::string, double>& s) override;
  // Probes rigid_centre, rigid_velocity (columns _x, _y(, _z)) and rigid_angular_velocity (one
  // column in 2D, _x, _y, _z in 3D) of the rigid body `body` (cluster_probes.cpp).
  std::vector<std::string> probe_columns(const ProbeSpec& s) const override;
  void probe(Simulation<D>& sim, const ProbeSpec& s, std::vector<double>& out) override;

  // Motion of a whole rigid body (all its clusters): centre of mass, velocity of the centre and
  // angular velocity I^-1 L of the clusters about that centre (2D: z component only). For a
  // body of one cluster these are the cluster's own values.
  struct BodyMotion {
    Vec<D> centre = Vec<D>::Zero(), velocity = Vec<D>::Zero();
    Vec3 omega = Vec3::Zero();
  };
  BodyMotion body_motion(int body) const;

  struct Cluster {
    int body = 0;
    double mass = 0;
    Vec<D> centre = Vec<D>::Zero(), velocity = Vec<D>::Zero(), force = Vec<D>::Zero();
    Vec3 torque = Vec3::Zero(), omega = Vec3::Zero();       // 2D: z components only
    double angle = 0, inertia = 0;                          // 2D: rotation angle, polar inertia
    Eigen::Quaterniond q = Eigen::Quaterniond::Identity();  // 3D: body -> world
    Vec3 momentum = Vec3::Zero();                           // 3D: world angular momentum L
    Mat3 inertia_body = Mat3::Zero(), inertia_body_inv = Mat3::Zero();  // 3D
    std::vector<std::size_t> members;
  };
  std::size_t size() const { return c_.size(); }
  const Cluster& cluster(std::size_t c) const { return c_[c]; }
  // World rotation of cluster c (body frame -> world).
  Mat<D> rotation(const Cluster& c) const;
  // Angular momentum about the cluster's centre (3D: L; 2D: z component).
  Vec3 angular_momentum(const Cluster& c) const;

 private:
  void collect_members(Simulation<D>& sim);  // member lists from the `cluster` field
  void mass_properties(Simulation<D>& sim);  // mass and inertia from members and offsets
  void set_members(Simulation<D>& sim, bool positions);
  Vec3 world_omega(const Cluster& c) const;  // 3D: I_w^-1 L
  Vec<D> min_image(Vec<D> d) const;

  int kcl_, koff_, kG_;
  std::vector<std::string> body_names_;  // of every body of the scene (probes name them)
  std::vector<Cluster> c_;
  std::vector<double> reduce_buf_;  // force and torque of all clusters (MPI sum)
  Vec<D> lo_, len_;
  std::array<bool, D> periodic_{};
};

}  // namespace monosph
