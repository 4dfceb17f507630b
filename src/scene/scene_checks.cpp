// Checks of a scene once read: `name` as a file name, expressions that evaluate to a non-finite
// value, and the size guard (particles and memory before anything is allocated).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>

#include "parallel/comm.hpp"
#include "scene/scene_parts.hpp"

namespace monosph {

namespace {

// Bytes a run needs per particle: peak resident set / particles, measured on 80k-190k particle
// runs (README, "Size guard"): 2D dam break 1.7 kB, plate 2.3 kB, AFM 2.4 kB; 3D acoustic wave
// 5.2 kB, Taylor bar (plasticity) 11.0 kB. Fields, neighbour lists, pair caches, module data and
// a frame being written.
double bytes_per_particle(const Scene& s) {
  if (s.dimension == 2) return 2500;
  const bool solid = std::any_of(s.bodies.begin(), s.bodies.end(),
                                 [](const BodySpec& b) { return b.phase == "solid"; });
  return solid ? 12000 : 6000;
}
constexpr double kProgramBytes = 35e6;  // the program and its libraries (measured 33.6 MB)

std::string bytes_text(double b) {
  const char* units[] = {"B", "kB", "MB", "GB", "TB", "PB", "EB"};
  int u = 0;
  while (b >= 1000 && u < 6) b /= 1000, ++u;
  return b >= 1e4 ? fmt::format("{:.2g} {}", b, units[u]) : fmt::format("{:.3g} {}", b, units[u]);
}

// A number from /proc or /sys (e.g. "MemAvailable:  123 kB", "max"); < 0 when there is none.
double read_number(const char* file, const std::string& label = "") {
  std::ifstream in(file);
  std::string word;
  while (in >> word) {
    if (!label.empty() && word != label) continue;
    if (!label.empty() && !(in >> word)) return -1;
    char* end = nullptr;
    const double v = std::strtod(word.c_str(), &end);
    return end && *end == '\0' ? v : -1;
  }
  return -1;
}

// Memory this process may still take: MemAvailable, capped by a cgroup memory limit.
double available_memory() {
  double avail = read_number("/proc/meminfo", "MemAvailable:") * 1024;
  const double v2 = read_number("/sys/fs/cgroup/memory.max");
  const double used = read_number("/sys/fs/cgroup/memory.current");
  if (v2 > 0 && used >= 0) avail = avail > 0 ? std::min(avail, v2 - used) : v2 - used;
  const double v1 = read_number("/sys/fs/cgroup/memory/memory.limit_in_bytes");
  const double used1 = read_number("/sys/fs/cgroup/memory/memory.usage_in_bytes");
  if (v1 > 0 && v1 < 1e18 && used1 >= 0)
    avail = avail > 0 ? std::min(avail, v1 - used1) : v1 - used1;
  return avail;
}

// MPI ranks on this machine (they share its memory), of all ranks.
double local_share() {
  int local = 1;
  for (const char* v : {"OMPI_COMM_WORLD_LOCAL_SIZE", "MPI_LOCALNRANKS"})
    if (const char* s = std::getenv(v)) local = std::max(local, std::atoi(s));
  return double(std::min(local, Comm::world().size())) / Comm::world().size();
}

std::string point_text(const Point& x) {
  std::string s = "(";
  for (std::size_t a = 0; a < x.size(); ++a) s += fmt::format("{}{:g}", a ? ", " : "", x[a]);
  return s + ")";
}

// Evaluates `text` at the points and times; a non-finite value (or, with `positive`, a value
// that is not positive) is an error naming the key, the value and the point.
void check_values(const std::string& text, const std::string& path, const Scene& s,
                  const std::vector<Point>& points, const std::vector<double>& times,
                  bool positive = false) {
  Expression e(text, path, s.variables);
  const std::vector<Point> at_origin = {Point()};  // an expression in t only
  for (double t : times)
    for (const auto& x : points.empty() ? at_origin : points) {
      const double v = e(x.empty() ? 0 : x[0], x.size() > 1 ? x[1] : 0, x.size() > 2 ? x[2] : 0, t);
      const bool bad = !std::isfinite(v) || (positive && !(v > 0));
      if (!bad) continue;
      const std::string where =
          (x.empty() ? "" : point_text(x)) +
          (e.depends_on_time() || x.empty() ? fmt::format("{}t = {:g}", x.empty() ? "" : ", ", t)
                                            : "");
      scene_error(path, "'" + text + "' is " +
                            (std::isfinite(v) ? fmt::format("not positive ({:g})", v)
                                              : std::string(std::isnan(v) ? "nan" : "inf")) +
                            " at " + where);
    }
}

// Lattice nodes of `shape` (at most about `count`, spread over it).
std::vector<Point> sample(const Scene& s, const Shape& shape, double count = 2000) {
  std::vector<Point> pts;
  walk_lattice(s, shape, count, [&](const Point& x) {
    pts.push_back(x);
    return true;
  });
  return pts;
}

Shape domain_box(const Scene& s) {
  Shape d;
  d.kind = Shape::Kind::Box;
  d.a = s.domain_min, d.b = s.domain_max;
  return d;
}

const BodySpec* find_body(const Scene& s, const std::string& name) {
  for (const auto& b : s.bodies)
    if (b.name == name) return &b;
  return nullptr;
}

void check_bodies(const Scene& s) {
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    const BodySpec& b = s.bodies[i];
    const std::string p = fmt::format("bodies[{}] ({}).initial.", i, b.name);
    if (b.density_expr.empty() && b.velocity_expr.empty()) continue;
    const auto pts = sample(s, b.shape);
    if (!b.density_expr.empty()) check_values(b.density_expr, p + "density", s, pts, {0.0}, true);
    for (std::size_t a = 0; a < b.velocity_expr.size(); ++a)
      check_values(b.velocity_expr[a], fmt::format("{}velocity[{}]", p, a), s, pts, {0.0});
  }
}

void check_boundaries(const Scene& s, const std::vector<double>& times) {
  for (std::size_t k = 0; k < s.boundaries.size(); ++k) {
    const BoundarySpec& bc = s.boundaries[k];
    std::vector<Point> pts;
    if (bc.point) pts = {*bc.point};
    if (bc.region) pts = sample(s, *bc.region);
    if (const BodySpec* b = find_body(s, bc.body)) pts = sample(s, b->shape);
    for (std::size_t a = 0; a < bc.velocity_expr.size(); ++a)
      if (bc.velocity_expr[a] != "free")
        check_values(bc.velocity_expr[a], fmt::format("boundary_conditions[{}].velocity[{}]", k, a),
                     s, pts, times);
  }
}

}  // namespace

namespace {
// The code point of a bidirectional embedding, override or isolate (U+202A-U+202E,
// U+2066-U+2069) that starts at text[i], else 0: they make a file name display reversed.
unsigned bidi_control_at(const std::string& text, std::size_t i) {
  if (i + 2 >= text.size() || static_cast<unsigned char>(text[i]) != 0xE2) return 0;
  const auto b1 = static_cast<unsigned char>(text[i + 1]);
  const auto b2 = static_cast<unsigned char>(text[i + 2]);
  const unsigned cp = 0x2000 + ((b1 & 0x3F) << 6) + (b2 & 0x3F);
  if ((b1 >> 6) != 2 || (b2 >> 6) != 2) return 0;
  return (cp >= 0x202A && cp <= 0x202E) || (cp >= 0x2066 && cp <= 0x2069) ? cp : 0;
}
}  // namespace

bool has_controls(const std::string& text) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto u = static_cast<unsigned char>(text[i]);
    if (u < 0x20 || u == 0x7f || bidi_control_at(text, i) != 0) return true;
  }
  return false;
}

std::string printable(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (const unsigned cp = bidi_control_at(text, i)) {
      out += fmt::format("\\u{:04X}", cp);
      i += 2;
      continue;
    }
    const auto u = static_cast<unsigned char>(text[i]);
    if (u >= 0x20 && u != 0x7f) {
      out.push_back(text[i]);
      continue;
    }
    out += fmt::format("\\x{:02x}", u);
  }
  return out;
}

void check_name(const std::string& name) {
  if (name.empty()) scene_error("name", "must not be empty (it names the output files)");
  if (name.size() > 200) scene_error("name", "longer than 200 characters");
  if (name == "." || name == ".." || has_controls(name) ||
      name.find_first_of("/\\") != std::string::npos)
    scene_error("name", fmt::format("'{}' is not a plain file name (it names the output files: "
                                    "no /, \\, control characters, bidirectional controls "
                                    "U+202A-U+202E and U+2066-U+2069, . or ..)",
                                    printable(name)));
}

void check_scene_expressions(const Scene& s) {
  const std::vector<double> times = {0.0, 0.5 * s.end_time, s.end_time};
  check_bodies(s);
  check_boundaries(s, times);
  for (std::size_t k = 0; k < s.surfaces.size(); ++k)
    for (std::size_t a = 0; a < s.surfaces[k].velocity_expr.size(); ++a)
      check_values(s.surfaces[k].velocity_expr[a],
                   fmt::format("surfaces[{}] ({}).velocity[{}]", k, s.surfaces[k].name, a), s, {},
                   times);
  const auto domain = sample(s, domain_box(s));
  for (std::size_t k = 0; k < s.probes.size(); ++k) {
    const ProbeSpec& ps = s.probes[k];
    if (ps.weight_expr.empty()) continue;
    const BodySpec* b = find_body(s, ps.body);
    check_values(ps.weight_expr, fmt::format("probes.list[{}] ({}).weight", k, ps.name), s,
                 b ? sample(s, b->shape) : domain, times);
  }
}

void check_size(const Scene& s) {
  bool exact = false;
  const double n = count_particles(s, &exact);
  const std::string count = exact ? fmt::format("{:.0f}", n) : fmt::format("about {:.2g}", n);
  const std::string head = fmt::format("{:g} gives {} particles", s.dp, count);
  if (s.max_particles > 0 && n > s.max_particles)
    scene_error("dp",
                fmt::format("{}, more than limits.max_particles ({:g})", head, s.max_particles));
  const double need = n * bytes_per_particle(s) * local_share() + kProgramBytes;
  const double limit = s.max_memory > 0 ? s.max_memory : available_memory();
  if (limit > 0 && need > limit)
    scene_error(
        "dp", fmt::format("{}, which need about {} of memory; {}", head, bytes_text(need),
                          s.max_memory > 0 ? "limits.max_memory is " + bytes_text(limit)
                                           : "this machine has " + bytes_text(limit) +
                                                 " available (limits.max_memory sets the limit)"));
}

}  // namespace monosph
