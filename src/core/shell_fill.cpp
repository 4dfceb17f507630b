#include "core/shell_fill.hpp"

#include <algorithm>
#include <cmath>

#include "core/types.hpp"

namespace monosph {

namespace {
constexpr double pi = 3.14159265358979323846;

// N points on the unit sphere by the Fibonacci spiral (Swinbank & Purser 2006): equal-area bands
// in z, longitude advancing by the golden angle; `turn` rotates the spiral about z.
void fibonacci(long n, double turn, std::vector<Point>& out) {
  const double golden = pi * (3.0 - std::sqrt(5.0));
  for (long j = 0; j < n; ++j) {
    const double z = 1.0 - (2.0 * j + 1.0) / n;
    const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = golden * j + turn;
    out.push_back({s * std::cos(phi), s * std::sin(phi), z});
  }
}

struct Shells {
  double r_out, dr;
  long n;
  double radius(long k) const { return r_out - (k + 0.5) * dr; }
};

Shells shells(const Shape& shape, double dp) {
  if (shape.kind != Shape::Kind::Sphere && shape.kind != Shape::Kind::Ring)
    throw InputError("fill: shells needs a sphere or ring shape");
  const double r_in = shape.kind == Shape::Kind::Ring ? shape.r0 : 0.0;
  const double r_out = shape.kind == Shape::Kind::Ring ? shape.r1 : shape.r0;
  const long n = std::max(1L, std::lround((r_out - r_in) / dp));
  return {r_out, (r_out - r_in) / n, n};
}

// Points on shell radius r: 2D 2 pi r / dp, 3D 4 pi r^2 / dp^2 (at least one).
long points_on(double r, int dim, double dp) {
  const double m = dim == 2 ? 2 * pi * r / dp : 4 * pi * r * r / (dp * dp);
  return std::max(1L, std::lround(m));
}
}  // namespace

double shell_point_count(const Shape& shape, int dim, double dp) {
  const Shells sh = shells(shape, dp);
  double total = 0;
  for (long k = 0; k < sh.n; ++k) total += static_cast<double>(points_on(sh.radius(k), dim, dp));
  return total;
}

std::vector<ShellPoint> shell_points(const Shape& shape, int dim, double dp) {
  const Shells sh = shells(shape, dp);
  std::vector<ShellPoint> pts;
  for (long k = 0; k < sh.n; ++k) {
    const double r = sh.radius(k), a = r + sh.dr / 2, b = r - sh.dr / 2;  // shell bounds
    const long m = points_on(r, dim, dp);
    std::vector<Point> dirs;
    if (dim == 2) {
      for (long j = 0; j < m; ++j) {
        const double t = 2 * pi * (j + 0.5 * (k % 2)) / m;  // alternate shells half a step
        dirs.push_back({std::cos(t), std::sin(t)});
      }
    } else {
      fibonacci(m, 0.7 * k, dirs);
    }
    const double shell_volume =
        dim == 2 ? pi * (a * a - b * b) : 4.0 / 3.0 * pi * (a * a * a - b * b * b);
    for (const Point& d : dirs) {
      Point x(dim);
      for (int c = 0; c < dim; ++c) x[c] = shape.center[c] + r * d[c];
      pts.push_back({x, shell_volume / static_cast<double>(m)});
    }
  }
  return pts;
}

}  // namespace monosph
