// Shapes of the scene: inside tests, bounding boxes and the lattice nodes they hold.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "core/shell_fill.hpp"
#include "scene/scene.hpp"

namespace monosph {

namespace {
double dist2(const Point& a, const Point& b) {
  double s = 0;
  for (std::size_t k = 0; k < a.size(); ++k) s += (a[k] - b[k]) * (a[k] - b[k]);
  return s;
}
}  // namespace

Point BodyRotation::apply(const Point& x, bool inverse) const {
  if (degrees == 0) return x;  // bit for bit the particles as filled
  const double th = (inverse ? -degrees : degrees) * std::numbers::pi / 180;
  const double c = std::cos(th), s = std::sin(th);
  Point r(x.size());
  Point v(x.size());
  for (std::size_t k = 0; k < x.size(); ++k) v[k] = x[k] - about[k];
  if (x.size() == 2) {
    r[0] = about[0] + c * v[0] - s * v[1];
    r[1] = about[1] + s * v[0] + c * v[1];
    return r;
  }
  // Rodrigues: v c + (k x v) s + k (k.v)(1 - c), k the unit axis.
  const Point& k = axis;
  const double kv = k[0] * v[0] + k[1] * v[1] + k[2] * v[2];
  const double kxv[3] = {k[1] * v[2] - k[2] * v[1], k[2] * v[0] - k[0] * v[2],
                         k[0] * v[1] - k[1] * v[0]};
  for (int a = 0; a < 3; ++a) r[a] = about[a] + v[a] * c + kxv[a] * s + k[a] * kv * (1 - c);
  return r;
}

bool Shape::contains(const Point& x) const {
  switch (kind) {
    case Kind::Box:
      for (std::size_t k = 0; k < x.size(); ++k)
        if (x[k] < a[k] || x[k] > b[k]) return false;
      return true;
    case Kind::Sphere:
      return dist2(x, center) <= r0 * r0;
    case Kind::Ring: {
      double d2 = dist2(x, center);
      return d2 >= r0 * r0 && d2 <= r1 * r1;
    }
    case Kind::Cylinder: {
      double axis2 = dist2(a, b), t = 0;
      for (int k = 0; k < 3; ++k) t += (x[k] - a[k]) * (b[k] - a[k]);
      t /= axis2;
      if (t < 0 || t > 1) return false;
      Point foot(3);
      for (int k = 0; k < 3; ++k) foot[k] = a[k] + t * (b[k] - a[k]);
      return dist2(x, foot) <= r0 * r0;
    }
    case Kind::Polygon: {  // even-odd rule
      bool in = false;
      const std::size_t n = vertices.size();
      for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
        const auto &p = vertices[i], &q = vertices[j];
        if ((p[1] > x[1]) != (q[1] > x[1]) &&
            x[0] < (q[0] - p[0]) * (x[1] - p[1]) / (q[1] - p[1]) + p[0])
          in = !in;
      }
      return in;
    }
    case Kind::Union:
      return std::any_of(parts.begin(), parts.end(), [&](const Shape& s) { return s.contains(x); });
    case Kind::Difference:
      if (!parts[0].contains(x)) return false;
      for (std::size_t k = 1; k < parts.size(); ++k)
        if (parts[k].contains(x)) return false;
      return true;
  }
  return false;
}

void Shape::bounds(Point& lo, Point& hi) const {
  switch (kind) {
    case Kind::Box:
      lo = a, hi = b;
      return;
    case Kind::Sphere:
    case Kind::Ring: {
      double r = kind == Kind::Sphere ? r0 : r1;
      lo = hi = center;
      for (std::size_t k = 0; k < center.size(); ++k) lo[k] -= r, hi[k] += r;
      return;
    }
    case Kind::Cylinder:
      lo = hi = a;
      for (int k = 0; k < 3; ++k) {  // the end discs reach r0 sqrt(1 - e_k^2) along axis k
        const double ek2 = (b[k] - a[k]) * (b[k] - a[k]) / dist2(a, b);
        const double reach = r0 * std::sqrt(std::max(0.0, 1 - ek2));
        lo[k] = std::min(a[k], b[k]) - reach;
        hi[k] = std::max(a[k], b[k]) + reach;
      }
      return;
    case Kind::Polygon:
      lo = hi = vertices[0];
      for (const auto& v : vertices)
        for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], v[k]), hi[k] = std::max(hi[k], v[k]);
      return;
    case Kind::Union:
      parts[0].bounds(lo, hi);
      for (std::size_t i = 1; i < parts.size(); ++i) {
        Point l, h;
        parts[i].bounds(l, h);
        for (std::size_t k = 0; k < lo.size(); ++k)
          lo[k] = std::min(lo[k], l[k]), hi[k] = std::max(hi[k], h[k]);
      }
      return;
    case Kind::Difference:
      parts[0].bounds(lo, hi);
      return;
  }
}

long walk_lattice(const Scene& s, const Shape& shape, double max_nodes,
                  const std::function<bool(const Point&)>& visit) {
  // As Simulation::fill_bodies: nodes at domain.min + (k + 1/2) dp, k in [k0, k1] per axis.
  // Doubles throughout: a tiny dp gives node counts no integer holds.
  const int dim = s.dimension;
  const double dp = s.dp;
  Point lo, hi;
  shape.bounds(lo, hi);
  std::array<double, 3> k0{}, n{};
  double total = 1;
  for (int a = 0; a < dim; ++a) {
    const double nk = std::floor((s.domain_max[a] - s.domain_min[a]) / dp + 0.5);
    k0[a] = std::max(0.0, std::floor((lo[a] - s.domain_min[a]) / dp - 0.5));
    const double k1 = std::min(nk - 1, std::ceil((hi[a] - s.domain_min[a]) / dp));
    n[a] = std::max(0.0, k1 - k0[a] + 1);
    total *= n[a];
  }
  if (!(total > 0)) return 1;
  const double stride =
      total <= max_nodes ? 1.0 : std::ceil(std::pow(total / max_nodes, 1.0 / dim));
  const double offset = std::floor(stride / 2);
  std::array<double, 3> j{};
  Point x(dim);
  while (true) {
    bool inside_box = true;
    for (int a = 0; a < dim; ++a) {
      const double k = k0[a] + j[a] * stride + offset;
      inside_box = inside_box && k < k0[a] + n[a];
      x[a] = s.domain_min[a] + (k + 0.5) * dp;
    }
    if (inside_box && shape.contains(x) && !visit(x)) break;
    int a = 0;
    while (a < dim && (++j[a]) * stride >= n[a]) j[a] = 0, ++a;
    if (a == dim) break;
  }
  return static_cast<long>(std::min(stride, 1e18));
}

double count_particles(const Scene& s, bool* exact) {
  // Bodies in fill order: `fill: rest` bodies last, taking only nodes no earlier body holds.
  std::vector<const BodySpec*> order;
  for (int pass = 0; pass < 2; ++pass)
    for (const auto& b : s.bodies)
      if (b.fill_rest == (pass == 1)) order.push_back(&b);
  double total = 0;
  bool all_exact = true;
  for (std::size_t i = 0; i < order.size(); ++i) {
    const BodySpec& b = *order[i];
    double count = 0;
    if (b.fill_shells) {  // body-fitted points, not lattice nodes: counted exactly
      total += shell_point_count(b.shape, s.dimension, s.dp);
      continue;
    }
    const long stride = walk_lattice(s, b.shape, 1e6, [&](const Point& x) {
      if (b.fill_rest)
        for (std::size_t o = 0; o < i; ++o)
          if (order[o]->shape.contains(x)) return true;
      count += 1;
      return true;
    });
    all_exact = all_exact && stride == 1;
    total += count * std::pow(double(stride), s.dimension);
  }
  if (exact) *exact = all_exact;
  return total;
}

KernelType kernel_from_name(const std::string& name) {
  if (name == "cubic_spline") return KernelType::CubicSpline;
  if (name == "wendland_c2") return KernelType::WendlandC2;
  if (name == "quintic_spline") return KernelType::QuinticSpline;
  throw InputError("kernel: '" + name +
                   "' is not allowed (allowed: cubic_spline, wendland_c2, quintic_spline)");
}

const char* kernel_name(KernelType t) {
  switch (t) {
    case KernelType::CubicSpline:
      return "cubic_spline";
    case KernelType::WendlandC2:
      return "wendland_c2";
    case KernelType::QuinticSpline:
      return "quintic_spline";
  }
  return "?";
}

}  // namespace monosph
