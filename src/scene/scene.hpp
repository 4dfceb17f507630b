#pragma once
// A scene: everything a run needs, read from YAML and validated (key path, value, what is
// allowed). Dimension-agnostic: vectors are std::vector<double> of length `dimension`.

#include <algorithm>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/kernel.hpp"
#include "scene/expression.hpp"
#include "scene/module_keys.hpp"

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

// A material's generic keys; each module reads its own (the solid's plasticity and damage, the
// fluid's cavitation and background pressure) into `params` (scene/module_keys.hpp).
struct Material {
  std::string name;
  double density = 0;        // rho0
  double bulk_modulus = 0;   // K, EOS p = K (rho/rho0 - 1) (MMB Eq. 13)
  double shear_modulus = 0;  // mu
  double heat_capacity = 0;  // C_p, J/(kg K); 0: no adiabatic heating (MMB Eq. 24)
  double viscosity = 0;      // dynamic viscosity mu (Pa s) of a fluid; nu = mu / rho0
  // Mass scaling f (key mass_scaling, >= 1): density is f rho0 and heat_capacity C_p / f, so
  // inertia grows f times (the time step sqrt(f)) while rho C_p, and with it every thermal
  // result, stays the material's (docs/theory.md, "Mass scaling").
  double mass_scaling = 1;
  // The temperature the material starts at unless a body gives one: 293.15 K, or the Johnson-Cook
  // reference temperature of a plastic material (set by the solid module).
  double reference_temperature = 293.15;
  ParamMap params;  // each module's parameters of this material
  double pressure(double rho) const { return bulk_modulus * (rho / density - 1.0); }  // Eq. 13
  double sound_speed() const;  // sqrt(K/rho0), used by artificial viscosity
  double wave_speed() const;   // sqrt((K + 4 mu/3)/rho0), used by the time step
  // A body's initial temperature: `given` (initial.temperature) when set, else the material's
  // reference temperature.
  double initial_temperature(double given) const {
    return given > 0 ? given : reference_temperature;
  }
  double youngs_modulus() const {
    return 9 * bulk_modulus * shear_modulus / (3 * bulk_modulus + shear_modulus);
  }
};

// Named materials shipped with the code (MMB Table 1): "Al6061-T6", "PMMA". Empty if unknown.
std::optional<Material> library_material(const std::string& name);
std::vector<std::string> library_material_names();

// A body's `rotate`: its particles turned by `degrees` about the point `about` (3D: about the
// unit `axis` through it; counter-clockwise seen from where the axis points) right after the
// fill, before anything reads them.
struct BodyRotation {
  double degrees = 0;
  Point about;
  Point axis{0, 0, 1};
  // x turned (inverse: turned back); x itself when degrees is 0.
  Point apply(const Point& x, bool inverse = false) const;
};

struct BodySpec {
  std::string name;
  std::string phase;      // fluid | solid | wall
  std::string continuum;  // solid bodies with the same continuum name interact as one body
  int material = 0;
  Shape shape;
  double jitter = 0;  // random displacement of lattice nodes, fraction of dp
  unsigned seed = 1;
  std::string density_expr;                // initial density (default rho0)
  std::vector<std::string> velocity_expr;  // initial velocity components
  double av_alpha = 0, av_beta = 0;        // artificial viscosity (MMB Eq. 17-18)
  double as_epsilon = 0, as_n = 4;         // artificial stress (MMB Eq. 19-20)
  double delta = 0;                        // density diffusion (MMB Eq. 21)
  // Stress divergence: false = normalised gradient (MMB Eq. 10-11); true = corrected gradient,
  // the adjoint of the corrected velocity gradient (Bonet & Lok 1999; docs/theory.md).
  bool corrected_divergence = false;
  // Solid formulation: 0 Eulerian-kernel MMB (stress divergence), 1 total Lagrangian, 2 essentially
  // non-hourglass updated Lagrangian (Zhang et al. 2024: shear force from a Laplacian).
  int formulation = 0;
  // `formulation: total_lagrangian`: reference-configuration kernels (Ganzenmueller 2015, Sect. 2)
  bool total_lagrangian = false;
  double temperature = 0;    // initial temperature, K (0: the material's T_ref)
  Point body_force;          // replaces the scene's body_force when given
  double damping = 0;        // mass-proportional damping rate c [1/s]: a -= c v
  bool fill_rest = false;    // takes only the lattice nodes no other body takes
  bool fill_shells = false;  // body-fitted concentric shells (sphere, ring; shell_fill.hpp)
  Point angular_velocity;    // rigid: initial (2D: one value; 3D: a vector)
  std::optional<BodyRotation> rotate;  // particles turned after the fill
  // Each module's parameters of this body, read by the module (scene/module_keys.hpp).
  ParamMap params;
};

struct BoundarySpec {
  std::string type;                        // fixed | velocity
  std::string body;                        // whole body, or
  std::optional<Shape> region;             // particles inside a region, or
  std::optional<Point> point;              // the one particle nearest to a point at the start
  std::vector<std::string> velocity_expr;  // in x, y, z, t
  std::string name;                        // probe name for the reaction force
};

// A rigid surface with prescribed motion (src/rigid; MMB 2020 Sect. 3): segments in 2D, triangles
// in 3D. Geometry is built by the rigid module; the scene only checks the keys and values.
struct SurfaceSpec {
  std::string name;
  std::string kind;  // box | plane | segment | polyline | polygon | rectangle | triangles | stl
  std::vector<Point> points;  // box: min, max; plane: point, normal; segment, polyline, polygon,
                              // rectangle: vertices; triangles: three corners per triangle
  double size[2] = {0, 0};    // plane: side lengths (one in 2D, two in 3D)
  std::string file;           // stl: path (relative to the scene file's folder)
  double scale = 1;           // every vertex x -> scale x + translate
  Point translate;
  std::vector<std::string> velocity_expr;  // prescribed velocity, expressions in t
  double friction = 0;                     // Coulomb coefficient mu_f
  double damping = 0;                      // normal dashpot, ratio of critical (0: elastic Hertz)
  double friction_limit = 0;               // limiting shear stress tau_max, Pa (0: none)
  double heat_partition = 1;               // share of the friction work the surface takes
  double heat_transfer = 0;                // contact conductance h_c, W/(m^2 K) (0: none)
  double temperature = 293.15;             // the surface's (fixed) temperature, K
  double stiffness = 0;                    // Young's modulus E_s; 0: rigid (E_s = infinity)
  double poisson_ratio = 0.3;              // nu_s (only with a stiffness)
};

struct ProbeSpec {
  std::string name, type, field, weight_expr, body;
  std::string target;  // penetration: the body penetrated (empty: every solid particle)
  int component = -1;
  Point point;
  Point axis;              // diameter, profile: unit direction (of the axis through `point`)
  Point normal;            // chip_ratio: the rake face's unit normal, into the chip
  std::string method;      // chip_ratio: layer, section (geometry) or flow (mass flux)
  int min_particles = 10;  // pieces: smaller clusters (spray, single particles) are not counted
  int bins = 0;            // profile: number of bins along `axis`
  Point range;             // profile: [lo, hi] along `axis` (empty: the default range)
  int columns = 1;         // columns in probes.csv (name, or name_x, name_y...; 0: profile)
  double size = 0;         // wall_pressure: sensor length (2D) or diameter (3D); centre in
                           // `point`, unit normal (wall into fluid) in `axis`
};

struct ReferenceSpec {
  std::string name, probe,
      measure;       // measure: frequency | period | final | max | min | mean | std | harmonic_mean
  double value = 0;  // NaN: no reference value (the measure is reported, no error)
  double start = 0;  // ignore probe samples before this time
  // Simulated time the measure needs (key needs_time). Default: a window measure (final, max,
  // min, mean) needs the scene's end time as written; a frequency, period or peak ratio only
  // needs `start` (it is measurable, or not, from the samples after it).
  double needs = -1;
  double needs_time(double scene_end_time) const {
    if (needs >= 0) return needs;
    const bool window = measure == "final" || measure == "max" || measure == "min" ||
                        measure == "mean" || measure == "harmonic_mean" || measure == "std";
    return window ? scene_end_time : start;
  }
};

// A pass criterion the run checks itself (summary.json "checks"; exit code 5 if one fails).
struct CheckSpec {
  std::string name, probe, measure;  // measure: as ReferenceSpec, or drift (max |y - y0| / |y0|)
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  double start = 0;
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
  // domain.mirror: symmetry planes at the faces domain.min[a] / domain.max[a].
  std::vector<bool> mirror_min, mirror_max;
  bool has_mirror() const {
    for (std::size_t a = 0; a < mirror_min.size(); ++a)
      if (mirror_min[a] || mirror_max[a]) return true;
    return false;
  }
  std::vector<Material> materials;
  std::vector<BodySpec> bodies;
  std::vector<BoundarySpec> boundaries;
  std::vector<SurfaceSpec> surfaces;  // rigid surfaces (section `surfaces`)
  ParamMap params;  // each module's parameters of its top-level section (contact, lubrication, ...)
  std::vector<std::string> modules;
  Point body_force;
  double end_time = 0;
  double reference_end_time = 0;  // end_time as the scene file gives it, before --set overrides
  double cfl = 0.3, force_factor = 0.25, max_dt = 0, dt_collapse = 1e-4;
  // Explicit Newmark (beta = 0): v_{n+1} = v_n + dt((1 - gamma) a_n + gamma a_{n+1}). 0.5 is
  // velocity Verlet (no numerical dissipation); gamma > 0.5 damps modes near the step frequency.
  double newmark_gamma = 0.5;
  // Multi-rate stepping (docs/theory.md): solids take up to max_substeps sub-steps per step.
  bool multi_rate = false;
  int max_substeps = 32;
  // Dual-criteria time stepping (Zhang et al. 2024, Eq. 21-25): the particle configuration
  // (pair geometry and kernel sums) is updated every advection step CFL_ad h / |v|max; the
  // acoustic steps in between use CFL_ac h / (c + |v|max). Off when advection_cfl is 0.
  double advection_cfl = 0, acoustic_cfl = 0.4;
  bool frozen_kernel = false;  // acoustic steps keep the kernel values too (Zhang et al.)
  double max_mach = 0.5, min_distance = 0.1;
  double output_every = 0, checkpoint_every = 0, probe_every = 0;
  std::vector<std::string> output_fields;
  std::vector<ProbeSpec> probes;
  std::vector<ReferenceSpec> references;
  std::vector<CheckSpec> checks;
  Constants variables;    // section `variables`: names every expression of the scene can use
  int reorder_every = 1;  // particles re-sorted in cell order every N neighbour builds
  // Section `limits` (the size guard): the most particles (0: no limit) and bytes (0: the memory
  // available on this machine) a run may need.
  double max_particles = 0, max_memory = 0;

  double h() const { return h_factor * dp; }
  int material_index(const std::string& name) const;  // -1 if unknown
};

// Calls visit(x) for the lattice nodes of the scene (those Simulation fills) inside `shape`, every
// stride-th node along each axis so that at most about max_nodes are visited; stops when visit
// returns false. Returns the stride (1: every node).
long walk_lattice(const Scene& s, const Shape& shape, double max_nodes,
                  const std::function<bool(const Point&)>& visit);

// Particles the lattice fill creates: exact (*exact = true) when every body's bounding box holds
// at most a million lattice nodes, else estimated on a coarser lattice. Never allocates.
double count_particles(const Scene& s, bool* exact = nullptr);

// Reads and validates a scene. `overrides` are "a.b.c=value" strings (command line --set).
// Throws InputError with a one-line message naming the key path.
Scene load_scene_file(const std::string& path, const std::vector<std::string>& overrides = {});
Scene load_scene_text(const std::string& text, const std::vector<std::string>& overrides = {},
                      const std::string& origin = "scene");

}  // namespace monosph
