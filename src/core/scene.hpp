#pragma once
// A scene: everything a run needs, read from YAML and validated (key path, value, what is
// allowed). Dimension-agnostic: vectors are std::vector<double> of length `dimension`.
#include <yaml-cpp/yaml.h>

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "kernel.hpp"

namespace monosph {

using Point = std::vector<double>;

// A geometric primitive or combination; `contains` is tested on lattice nodes.
struct Shape {
  enum class Kind { Box, Sphere, Ring, Cylinder, Polygon, Union, Difference } kind;
  Point a, b;                   // box min/max; cylinder start/end
  Point center;                 // sphere, ring
  double r0 = 0, r1 = 0;        // radius; ring inner/outer
  std::vector<Point> vertices;  // polygon
  std::vector<Shape> parts;     // union: any; difference: first minus the rest
  bool contains(const Point& x) const;
  void bounds(Point& lo, Point& hi) const;  // axis-aligned bounding box
};

struct Material {
  std::string name;
  double density = 0;          // rho0
  double bulk_modulus = 0;     // K, EOS p = K (rho/rho0 - 1) (MMB Eq. 13)
  double shear_modulus = 0;    // mu
  double sound_speed() const;  // sqrt(K/rho0), used by artificial viscosity
  double wave_speed() const;   // sqrt((K + 4 mu/3)/rho0), used by the time step
};

struct BodySpec {
  std::string name;
  std::string phase;      // fluid | solid
  std::string continuum;  // solid bodies with the same continuum name interact as one body
  int material = 0;
  Shape shape;
  double jitter = 0;  // random displacement of lattice nodes, fraction of dp
  unsigned seed = 1;
  std::string density_expr;                   // initial density (default rho0)
  std::vector<std::string> velocity_expr;     // initial velocity components
  double av_alpha = 0, av_beta = 0;           // artificial viscosity (MMB Eq. 17-18)
  double as_epsilon = 0, as_n = 4;            // artificial stress (MMB Eq. 19-20)
  double delta = 0;                           // density diffusion (MMB Eq. 21)
  double hg_xi = 0, hg_zeta = 0, hg_chi = 0;  // hourglass control (MMB Eq. 32-34)
  int hg_reference = 0;  // error vector against: 0 initial (MMB), 1 intermediate, 2 least squares
  // Stress divergence: false = normalised gradient (MMB Eq. 10-11); true = corrected gradient,
  // the adjoint of the corrected velocity gradient (Bonet & Lok 1999; docs/theory.md).
  bool corrected_divergence = false;
};

struct BoundarySpec {
  std::string type;                        // fixed | velocity
  std::string body;                        // whole body, or
  std::optional<Shape> region;             // particles inside a region
  std::vector<std::string> velocity_expr;  // in x, y, z, t
  std::string name;                        // probe name for the reaction force
};

struct ProbeSpec {
  std::string name, type, field, weight_expr, body;
  int component = -1;
  Point point;
};

struct ReferenceSpec {
  std::string name, probe, measure;  // measure: frequency | period | final | max | min | mean
  double value = 0;
  double start = 0;  // ignore probe samples before this time
};

struct Scene {
  std::string name, description, yaml;  // yaml: the (overridden) source text
  int dimension = 2;
  double dp = 0;
  KernelType kernel = KernelType::CubicSpline;
  double h_factor = 1.3;
  double skin_factor = 0.3;  // Verlet skin as a fraction of h
  Point domain_min, domain_max;
  std::vector<bool> periodic;
  std::vector<Material> materials;
  std::vector<BodySpec> bodies;
  std::vector<BoundarySpec> boundaries;
  std::vector<std::string> modules;
  Point body_force;
  double end_time = 0;
  double cfl = 0.3, force_factor = 0.25, max_dt = 0, dt_collapse = 1e-4;
  double max_mach = 0.5, min_distance = 0.1;
  double output_every = 0, checkpoint_every = 0, probe_every = 0;
  std::vector<std::string> output_fields;
  std::vector<ProbeSpec> probes;
  std::vector<ReferenceSpec> references;
  int reorder_every = 1;  // particles re-sorted in cell order every N neighbour builds

  double h() const { return h_factor * dp; }
  int material_index(const std::string& name) const;  // -1 if unknown
};

// Reads and validates a scene. `overrides` are "a.b.c=value" strings (command line --set).
// Throws InputError with a one-line message naming the key path.
Scene load_scene_file(const std::string& path, const std::vector<std::string>& overrides = {});
Scene load_scene_text(const std::string& text, const std::vector<std::string>& overrides = {},
                      const std::string& origin = "scene");

}  // namespace monosph
