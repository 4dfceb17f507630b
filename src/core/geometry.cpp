// Shapes of the scene: inside tests and bounding boxes.
#include <algorithm>
#include <cmath>

#include "scene.hpp"

namespace monosph {

namespace {
double dist2(const Point& a, const Point& b) {
  double s = 0;
  for (std::size_t k = 0; k < a.size(); ++k) s += (a[k] - b[k]) * (a[k] - b[k]);
  return s;
}
}  // namespace

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
