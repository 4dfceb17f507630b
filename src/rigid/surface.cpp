#include "surface.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numeric>
#include <sstream>

namespace monosph {

template <int D>
Vec<D> closest_point_on_segment(const Vec<D>& p, const Vec<D>& a, const Vec<D>& b) {
  // Ericson Sect. 5.1.2: project p on the line, clamp the parameter to [0, 1].
  const Vec<D> ab = b - a;
  const double t = (p - a).dot(ab);
  if (t <= 0) return a;
  const double den = ab.squaredNorm();
  if (t >= den) return b;
  return a + (t / den) * ab;
}

Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  // Ericson Sect. 5.1.5 (ClosestPtPointTriangle): Voronoi regions of the vertices, edges, face.
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;  // vertex region a
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;  // vertex region b
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;  // edge ab
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;  // vertex region c
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;  // edge ac
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)  // edge bc
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double den = 1.0 / (va + vb + vc);  // face: barycentric (va, vb, vc)/(va + vb + vc)
  return a + ab * (vb * den) + ac * (vc * den);
}

template <int D>
Vec<D> closest_point_on_element(const Vec<D>& p, const SurfaceElement<D>& e) {
  if constexpr (D == 2)
    return closest_point_on_segment<2>(p, e.v[0], e.v[1]);
  else
    return closest_point_on_triangle(p, e.v[0], e.v[1], e.v[2]);
}

template <int D>
bool make_element(const std::array<Vec<D>, D>& v, SurfaceElement<D>& e) {
  e.v = v;
  if constexpr (D == 2) {
    const Vec<2> d = v[1] - v[0];
    const double len = d.norm();
    if (!(len > 0)) return false;
    e.normal = Vec<2>(d[1], -d[0]) / len;
  } else {
    const Vec3 n = (v[1] - v[0]).cross(v[2] - v[0]);
    const double area2 = n.norm();
    // Zero area relative to the longest edge squared: a degenerate (needle or point) triangle.
    const double scale = std::max(
        {(v[1] - v[0]).squaredNorm(), (v[2] - v[1]).squaredNorm(), (v[0] - v[2]).squaredNorm()});
    if (!(area2 > 1e-14 * scale)) return false;
    e.normal = n / area2;
  }
  return e.normal.allFinite();
}

// ---- bounding-box tree ----

template <int D>
SurfaceGeometry<D>::SurfaceGeometry(std::vector<SurfaceElement<D>> elements)
    : el_(std::move(elements)) {
  order_.resize(el_.size());
  std::iota(order_.begin(), order_.end(), 0);
  if (!el_.empty()) {
    nodes_.reserve(2 * el_.size());
    build(0, static_cast<int>(el_.size()));
  }
}

template <int D>
int SurfaceGeometry<D>::build(int first, int count) {
  Node node;
  node.lo.setConstant(std::numeric_limits<double>::infinity());
  node.hi.setConstant(-std::numeric_limits<double>::infinity());
  Vec<D> clo = node.lo, chi = node.hi;  // box of the element centres
  for (int k = first; k < first + count; ++k) {
    const auto& e = el_[order_[k]];
    Vec<D> centre = Vec<D>::Zero();
    for (const auto& v : e.v) {
      node.lo = node.lo.cwiseMin(v);
      node.hi = node.hi.cwiseMax(v);
      centre += v / D;
    }
    clo = clo.cwiseMin(centre);
    chi = chi.cwiseMax(centre);
  }
  const int index = static_cast<int>(nodes_.size());
  nodes_.push_back(node);
  if (count <= 4) {
    nodes_[index].first = first;
    nodes_[index].count = count;
    return index;
  }
  int axis = 0;
  (chi - clo).maxCoeff(&axis);
  auto centre = [&](int i) {
    double s = 0;
    for (const auto& v : el_[i].v) s += v[axis];
    return s;
  };
  const int half = count / 2;
  std::nth_element(order_.begin() + first, order_.begin() + first + half,
                   order_.begin() + first + count, [&](int a, int b) {
                     const double ca = centre(a), cb = centre(b);
                     return ca < cb || (ca == cb && a < b);
                   });
  const int left = build(first, half);
  const int right = build(first + half, count - half);
  nodes_[index].left = left;
  nodes_[index].right = right;
  return index;
}

template <int D>
bool SurfaceGeometry<D>::closest(const Vec<D>& p, double radius, Vec<D>& c, int& element) const {
  if (nodes_.empty()) return false;
  double best = radius * radius;
  element = -1;
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  auto box_distance2 = [&](const Node& n) {
    return (n.lo - p).cwiseMax(p - n.hi).cwiseMax(0.0).squaredNorm();
  };
  while (top > 0) {
    const Node& n = nodes_[stack[--top]];
    if (box_distance2(n) >= best) continue;
    if (n.left < 0) {
      for (int k = n.first; k < n.first + n.count; ++k) {
        const int i = order_[k];
        const Vec<D> q = closest_point_on_element<D>(p, el_[i]);
        const double d2 = (p - q).squaredNorm();
        if (d2 < best || (d2 == best && element >= 0 && i < element)) best = d2, c = q, element = i;
      }
    } else if (top + 2 <= 128) {
      // Nearer child last, so that it is searched first and prunes the other.
      const double dl = box_distance2(nodes_[n.left]), dr = box_distance2(nodes_[n.right]);
      stack[top++] = dl < dr ? n.right : n.left;
      stack[top++] = dl < dr ? n.left : n.right;
    } else {
      throw std::logic_error("SurfaceGeometry: tree deeper than its search stack");
    }
  }
  return element >= 0;
}

template <int D>
bool SurfaceGeometry<D>::closest_brute_force(const Vec<D>& p, double radius, Vec<D>& c,
                                             int& element) const {
  double best = radius * radius;
  element = -1;
  for (std::size_t i = 0; i < el_.size(); ++i) {
    const Vec<D> q = closest_point_on_element<D>(p, el_[i]);
    const double d2 = (p - q).squaredNorm();
    if (d2 < best) best = d2, c = q, element = static_cast<int>(i);
  }
  return element >= 0;
}

// ---- STL ----

namespace {

[[noreturn]] void stl_error(const std::string& file, const std::string& msg) {
  throw InputError(file + ": " + msg);
}

void add_triangle(std::vector<std::array<Vec3, 3>>& out, const std::array<Vec3, 3>& t) {
  SurfaceElement<3> e;
  if (make_element<3>(t, e)) out.push_back(t);
}

}  // namespace

std::vector<std::array<Vec3, 3>> read_stl(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) stl_error(file, "cannot read STL file");
  std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<std::array<Vec3, 3>> out;
  std::size_t read = 0;
  bool binary = false;
  if (data.size() >= 84) {
    std::uint32_t n;
    std::memcpy(&n, data.data() + 80, 4);
    binary = data.size() == 84 + 50 * static_cast<std::size_t>(n);
  }
  if (binary) {
    std::uint32_t n;
    std::memcpy(&n, data.data() + 80, 4);
    for (std::uint32_t k = 0; k < n; ++k) {
      const char* rec = data.data() + 84 + 50 * static_cast<std::size_t>(k);
      std::array<Vec3, 3> t;
      for (int c = 0; c < 3; ++c)
        for (int a = 0; a < 3; ++a) {
          float f;
          std::memcpy(&f, rec + 12 + 12 * c + 4 * a, 4);
          if (!std::isfinite(f))
            stl_error(file, "non-finite coordinate in triangle " + std::to_string(k));
          t[c][a] = f;
        }
      ++read;
      add_triangle(out, t);
    }
  } else {
    std::istringstream ss(data);
    std::string word;
    if (!(ss >> word) || word != "solid")
      stl_error(file, "not an STL file (neither 'solid ...' ASCII nor binary of matching size)");
    std::array<Vec3, 3> t;
    int corner = 0;
    while (ss >> word) {
      if (word == "vertex") {
        if (corner == 3)
          stl_error(file, "facet " + std::to_string(read) + " has more than 3 vertices");
        for (int a = 0; a < 3; ++a) {
          std::string num;
          if (!(ss >> num)) stl_error(file, "truncated vertex in facet " + std::to_string(read));
          char* end = nullptr;
          t[corner][a] = std::strtod(num.c_str(), &end);
          if (end == num.c_str() || *end != '\0' || !std::isfinite(t[corner][a]))
            stl_error(file, "bad coordinate '" + num + "' in facet " + std::to_string(read));
        }
        ++corner;
      } else if (word == "endfacet") {
        if (corner != 3) stl_error(file, "facet " + std::to_string(read) + " without 3 vertices");
        corner = 0;
        ++read;
        add_triangle(out, t);
      }
    }
    if (corner != 0) stl_error(file, "truncated last facet");
  }
  if (out.empty())
    stl_error(file, read ? "all " + std::to_string(read) + " triangles are degenerate"
                         : "contains no triangle");
  return out;
}

void write_stl(const std::string& file, const std::vector<std::array<Vec3, 3>>& triangles,
               bool binary) {
  std::ofstream out(file, std::ios::binary);
  if (!out) throw InputError(file + ": cannot write STL file");
  auto normal = [](const std::array<Vec3, 3>& t) {
    Vec3 n = (t[1] - t[0]).cross(t[2] - t[0]);
    return n.norm() > 0 ? Vec3(n / n.norm()) : Vec3(Vec3::Zero());
  };
  if (binary) {
    char header[80] = "monosph binary STL";
    out.write(header, 80);
    const std::uint32_t n = static_cast<std::uint32_t>(triangles.size());
    out.write(reinterpret_cast<const char*>(&n), 4);
    for (const auto& t : triangles) {
      float f[12];
      const Vec3 nn = normal(t);
      for (int a = 0; a < 3; ++a) f[a] = static_cast<float>(nn[a]);
      for (int c = 0; c < 3; ++c)
        for (int a = 0; a < 3; ++a) f[3 + 3 * c + a] = static_cast<float>(t[c][a]);
      out.write(reinterpret_cast<const char*>(f), 48);
      const std::uint16_t attr = 0;
      out.write(reinterpret_cast<const char*>(&attr), 2);
    }
  } else {
    out.precision(17);
    out << "solid monosph\n";
    for (const auto& t : triangles) {
      const Vec3 nn = normal(t);
      out << "  facet normal " << nn[0] << " " << nn[1] << " " << nn[2] << "\n    outer loop\n";
      for (const auto& v : t) out << "      vertex " << v[0] << " " << v[1] << " " << v[2] << "\n";
      out << "    endloop\n  endfacet\n";
    }
    out << "endsolid monosph\n";
  }
  if (!out) throw InputError(file + ": cannot write STL file");
}

// ---- elements of a scene surface ----

namespace {

template <int D>
Vec<D> vec(const Point& p) {
  Vec<D> v;
  for (int a = 0; a < D; ++a) v[a] = p[a];
  return v;
}

// Orients every triangle of a closed convex set so that its normal points away from `inside`.
void orient_outward(std::vector<std::array<Vec3, 3>>& tris, const Vec3& inside) {
  for (auto& t : tris)
    if ((t[1] - t[0]).cross(t[2] - t[0]).dot(t[0] - inside) < 0) std::swap(t[1], t[2]);
}

}  // namespace

template <int D>
std::vector<SurfaceElement<D>> surface_elements(const SurfaceSpec& s, const std::string& where) {
  using V = Vec<D>;
  std::vector<std::array<V, D>> raw;
  const std::string at = where + "." + s.kind;
  if constexpr (D == 2) {
    std::vector<V> pts;
    bool closed = false;
    if (s.kind == "box") {
      const V lo = vec<2>(s.points[0]), hi = vec<2>(s.points[1]);
      pts = {lo, V(hi[0], lo[1]), hi, V(lo[0], hi[1])};  // counter-clockwise
      closed = true;
    } else if (s.kind == "plane") {
      const V p = vec<2>(s.points[0]), n = vec<2>(s.points[1]).normalized();
      const V d(-n[1], n[0]);  // turned clockwise it gives n
      pts = {p - 0.5 * s.size[0] * d, p + 0.5 * s.size[0] * d};
    } else if (s.kind == "segment" || s.kind == "polyline" || s.kind == "polygon") {
      for (const auto& q : s.points) pts.push_back(vec<2>(q));
      closed = s.kind == "polygon";
      if (closed) {  // counter-clockwise, so that the normals point out
        double area = 0;
        for (std::size_t k = 0; k < pts.size(); ++k) {
          const V& a = pts[k];
          const V& b = pts[(k + 1) % pts.size()];
          area += a[0] * b[1] - b[0] * a[1];
        }
        if (area == 0) throw InputError(at + ": the polygon has zero area");
        if (area < 0) std::reverse(pts.begin(), pts.end());
      }
    } else {
      throw InputError(at + ": not a 2D surface");
    }
    for (std::size_t k = 0; k + 1 < pts.size(); ++k) raw.push_back({pts[k], pts[k + 1]});
    if (closed) raw.push_back({pts.back(), pts.front()});
  } else {
    std::vector<std::array<Vec3, 3>> tris;
    if (s.kind == "box") {
      const Vec3 lo = vec<3>(s.points[0]), hi = vec<3>(s.points[1]);
      auto corner = [&](int i, int j, int k) {
        return Vec3(i ? hi[0] : lo[0], j ? hi[1] : lo[1], k ? hi[2] : lo[2]);
      };
      for (int a = 0; a < 3; ++a)
        for (int side = 0; side < 2; ++side) {
          std::array<Vec3, 4> q;
          for (int m = 0; m < 4; ++m) {
            int c[3];
            c[a] = side;
            c[(a + 1) % 3] = m == 1 || m == 2;
            c[(a + 2) % 3] = m >= 2;
            q[m] = corner(c[0], c[1], c[2]);
          }
          tris.push_back({q[0], q[1], q[2]});
          tris.push_back({q[0], q[2], q[3]});
        }
      orient_outward(tris, 0.5 * (lo + hi));
    } else if (s.kind == "plane") {
      const Vec3 p = vec<3>(s.points[0]), n = vec<3>(s.points[1]).normalized();
      // In-plane axes: u from the coordinate axis least aligned with n, v = n x u (u x v = n).
      int k = 0;
      n.cwiseAbs().minCoeff(&k);
      Vec3 u = Vec3::Unit(k);
      u = (u - u.dot(n) * n).normalized();
      const Vec3 v = n.cross(u);
      const Vec3 a = 0.5 * s.size[0] * u, b = 0.5 * s.size[1] * v;
      tris.push_back({p - a - b, p + a - b, p + a + b});
      tris.push_back({p - a - b, p + a + b, p - a + b});
    } else if (s.kind == "rectangle") {
      std::array<Vec3, 4> q;
      for (int m = 0; m < 4; ++m) q[m] = vec<3>(s.points[m]);
      tris.push_back({q[0], q[1], q[2]});
      tris.push_back({q[0], q[2], q[3]});
    } else if (s.kind == "triangles") {
      for (std::size_t k = 0; k + 2 < s.points.size(); k += 3)
        tris.push_back({vec<3>(s.points[k]), vec<3>(s.points[k + 1]), vec<3>(s.points[k + 2])});
    } else if (s.kind == "stl") {
      tris = read_stl(s.file);
    } else {
      throw InputError(at + ": not a 3D surface");
    }
    for (const auto& t : tris) raw.push_back(t);
  }
  const V shift = vec<D>(s.translate);
  std::vector<SurfaceElement<D>> out;
  for (std::size_t k = 0; k < raw.size(); ++k) {
    std::array<V, D> v;
    for (int c = 0; c < D; ++c) v[c] = s.scale * raw[k][c] + shift;
    SurfaceElement<D> e;
    if (make_element<D>(v, e))
      out.push_back(e);
    else if (s.kind != "stl")  // STL files may hold slivers; given ones are errors
      throw InputError(at + ": element " + std::to_string(k) + " is degenerate (" +
                       (D == 2 ? "zero length)" : "zero area)"));
  }
  if (out.empty()) throw InputError(at + ": no surface element");
  return out;
}

template <int D>
Vec<D> contact_force(const Vec<D>& x, const Vec<D>& v, double m, const Vec<D>& c,
                     const Vec<D>& normal, const Vec<D>& v_surface, double radius, double e_star,
                     double friction, double dt, double depth, double* fn, double damping,
                     double friction_cap, double* power) {
  const Vec<D> d = x - c;
  const double dist = d.norm();
  const double overlap = radius - dist;
  if (fn) *fn = 0;
  if (power) *power = 0;
  if (!(overlap > 0)) return Vec<D>::Zero();
  // Direction from the closest point to the particle centre (not the face normal at edges and
  // vertices); the element normal only for a centre on the element.
  const Vec<D> n = dist > 1e-12 * radius ? Vec<D>(d / dist) : normal;
  double f_n = hertz_force(e_star, radius, overlap) / depth;
  const Vec<D> vr = v - v_surface;
  if (damping > 0) {
    const double kn = 1.5 * f_n / overlap;
    f_n = std::max(0.0, f_n - 2 * damping * std::sqrt(m * kn) * vr.dot(n));
  }
  if (fn) *fn = f_n;
  Vec<D> f = f_n * n;
  if (friction > 0) {
    const Vec<D> vt = vr - vr.dot(n) * n;
    const double s = vt.norm();
    if (s > 0) {
      // Coulomb up to the limiting shear force, regularised: never more than stops the sliding
      double f_t = std::min(friction * f_n, friction_cap);
      if (dt > 0) f_t = std::min(f_t, m * s / dt);
      f -= (f_t / s) * vt;
      // the mean sliding speed over the step the force stops (for the cap: all of m s^2 / 2)
      if (power) *power = f_t * std::max(0.0, s - (dt > 0 ? 0.5 * f_t * dt / m : 0.0));
    }
  }
  return f;
}

double contact_modulus(double bulk, double shear, double e_s, double nu_s) {
  double compliance;  // (1 - nu^2)/E of the particle material
  if (shear > 0) {
    const double e = 9 * bulk * shear / (3 * bulk + shear);
    const double nu = (3 * bulk - 2 * shear) / (2 * (3 * bulk + shear));
    compliance = (1 - nu * nu) / e;
  } else {
    compliance = 1 / bulk;  // fluid: E/(1 - nu^2) := K (see the header)
  }
  if (e_s > 0) compliance += (1 - nu_s * nu_s) / e_s;
  return 1 / compliance;
}

template Vec<2> closest_point_on_segment<2>(const Vec<2>&, const Vec<2>&, const Vec<2>&);
template Vec<3> closest_point_on_segment<3>(const Vec<3>&, const Vec<3>&, const Vec<3>&);
template Vec<2> closest_point_on_element<2>(const Vec<2>&, const SurfaceElement<2>&);
template Vec<3> closest_point_on_element<3>(const Vec<3>&, const SurfaceElement<3>&);
template bool make_element<2>(const std::array<Vec<2>, 2>&, SurfaceElement<2>&);
template bool make_element<3>(const std::array<Vec<3>, 3>&, SurfaceElement<3>&);
template class SurfaceGeometry<2>;
template class SurfaceGeometry<3>;
template std::vector<SurfaceElement<2>> surface_elements<2>(const SurfaceSpec&, const std::string&);
template std::vector<SurfaceElement<3>> surface_elements<3>(const SurfaceSpec&, const std::string&);
template Vec<2> contact_force<2>(const Vec<2>&, const Vec<2>&, double, const Vec<2>&, const Vec<2>&,
                                 const Vec<2>&, double, double, double, double, double, double*,
                                 double, double, double*);
template Vec<3> contact_force<3>(const Vec<3>&, const Vec<3>&, double, const Vec<3>&, const Vec<3>&,
                                 const Vec<3>&, double, double, double, double, double, double*,
                                 double, double, double*);

}  // namespace monosph
