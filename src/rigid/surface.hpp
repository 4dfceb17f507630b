#pragma once
#include <limits>
// Rigid surfaces (Mohseni-Mofidi & Bierwisch 2020, "MMB", Sect. 3, first paragraph): segments in
// 2D and triangles in 3D, from primitives or STL files; closest points (Ericson 2005, Real-Time
// Collision Detection, Sect. 5.1.2 and 5.1.5) and a bounding-volume tree to find the closest
// element of a surface near a particle.
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "core/hertz.hpp"
#include "core/types.hpp"
#include "scene/scene.hpp"

namespace monosph {

// A segment (D = 2) or triangle (D = 3) with its unit normal. Segment a -> b: the normal is the
// direction turned clockwise, n = (dy, -dx)/|d|, so a counter-clockwise polygon has outward
// normals. Triangle a, b, c: n = (b - a) x (c - a)/|.|, outward for counter-clockwise corners seen
// from outside (the STL convention). The normal is used only for a particle exactly on the element.
template <int D>
struct SurfaceElement {
  std::array<Vec<D>, D> v;
  Vec<D> normal;
};

// Closest point to p on the segment a-b (Ericson Sect. 5.1.2).
template <int D>
Vec<D> closest_point_on_segment(const Vec<D>& p, const Vec<D>& a, const Vec<D>& b);
// Closest point to p on the triangle a, b, c: face, edge or vertex region (Ericson Sect. 5.1.5).
Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);
// Closest point on one element (segment in 2D, triangle in 3D).
template <int D>
Vec<D> closest_point_on_element(const Vec<D>& p, const SurfaceElement<D>& e);

// Element with its normal from the corners; false for a degenerate (zero-length or zero-area) one.
template <int D>
bool make_element(const std::array<Vec<D>, D>& v, SurfaceElement<D>& e);

// The elements of one surface in its own (body) frame, with an axis-aligned bounding-box tree.
template <int D>
class SurfaceGeometry {
 public:
  SurfaceGeometry() = default;
  explicit SurfaceGeometry(std::vector<SurfaceElement<D>> elements);
  const std::vector<SurfaceElement<D>>& elements() const { return el_; }
  // The closest point c of all elements to p if it lies closer than `radius` (element index in
  // `element`); false when no element comes that close. Ties go to the lower element index.
  bool closest(const Vec<D>& p, double radius, Vec<D>& c, int& element) const;
  // The same by checking every element (tests).
  bool closest_brute_force(const Vec<D>& p, double radius, Vec<D>& c, int& element) const;
  Vec<D> lower() const { return nodes_.empty() ? Vec<D>::Zero() : nodes_[0].lo; }
  Vec<D> upper() const { return nodes_.empty() ? Vec<D>::Zero() : nodes_[0].hi; }

 private:
  struct Node {
    Vec<D> lo, hi;
    int left = -1, right = -1;  // children (inner node) or -1 (leaf)
    int first = 0, count = 0;   // leaf: order_[first, first + count)
  };
  int build(int first, int count);
  std::vector<SurfaceElement<D>> el_;
  std::vector<int> order_;
  std::vector<Node> nodes_;
};

// Triangles of an STL file (ASCII or binary; binary when the size is 84 + 50 n bytes for the n in
// its header). Normals are recomputed from the corners (counter-clockwise seen from outside);
// degenerate triangles are dropped. Throws InputError "<file>: <problem>".
std::vector<std::array<Vec3, 3>> read_stl(const std::string& file);
void write_stl(const std::string& file, const std::vector<std::array<Vec3, 3>>& triangles,
               bool binary);

// The elements a scene's surface describes (box, plane, segment, polyline, polygon, rectangle,
// triangles, stl), scaled and translated, in the frame of the surface at t = 0. `where` names the
// scene key in errors (InputError).
template <int D>
std::vector<SurfaceElement<D>> surface_elements(const SurfaceSpec& spec, const std::string& where);

// Contact modulus 1/E* = (1 - nu_p^2)/E_p + (1 - nu_s^2)/E_s of a particle material (K, mu) and a
// surface of Young's modulus e_s (0: rigid, no term) and Poisson ratio nu_s. E = 9K mu/(3K + mu),
// nu = (3K - 2mu)/(2(3K + mu)). A fluid (mu = 0) would have E = 0 and no contact at all; it
// takes its bulk modulus as the plane-strain modulus instead, E/(1 - nu^2) := K, so the surface
// repels it as stiffly as the (weakly compressible) fluid resists compression.
double contact_modulus(double bulk, double shear, double e_s, double nu_s);

// Force on a particle touching a surface element at its closest point c (MMB Sect. 3): Hertz
// normal force along n = (x - c)/|x - c| (the element normal when x lies on it) plus regularised
// Coulomb friction opposing the relative tangential velocity v_t = (v - v_s) - ((v - v_s).n) n,
// |F_t| = min(mu_f F_n, m |v_t| / dt) (it cannot reverse the sliding within a step; no cap when
// dt <= 0). `depth` divides the force: 1 in 3D, dp in 2D (a sphere's force per metre of a plane-
// strain slab, whose mass m is per metre). Returns the force; `fn` the normal force magnitude.
// `damping` (ratio of critical, default 0 = MMB's purely elastic Hertz contact) adds the normal
// dashpot -2 damping sqrt(m k_n) v_n with k_n = dF_n/d(delta) = 1.5 F_n/delta (Tsuji et al. 1992
// form); the normal force stays repulsive. `friction_cap` bounds |F_t| too: the limiting shear
// stress tau_max times the particle's contact area dp^(D-1) (tau = min(mu sigma_n, tau_max),
// Zorev's sticking-sliding law). `power`: the friction work rate |F_t| (|v_t| - |F_t| dt/(2m)),
// the force times the mean sliding speed over a step it decelerates uniformly.
template <int D>
Vec<D> contact_force(const Vec<D>& x, const Vec<D>& v, double m, const Vec<D>& c,
                     const Vec<D>& normal, const Vec<D>& v_surface, double radius, double e_star,
                     double friction, double dt, double depth, double* fn = nullptr,
                     double damping = 0,
                     double friction_cap = std::numeric_limits<double>::infinity(),
                     double* power = nullptr);

}  // namespace monosph
