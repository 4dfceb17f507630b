#pragma once
// Simulation<D>: the particle container, neighbours, modules and the kick-drift-kick integrator.
#include <chrono>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/kernel.hpp"
#include "core/mirror.hpp"
#include "core/neighbours.hpp"
#include "core/particles.hpp"
#include "parallel/comm.hpp"
#include "parallel/decomposition.hpp"
#include "scene/expression.hpp"
#include "scene/scene.hpp"

namespace monosph {

template <int D>
class Simulation;

// Physics comes as modules; a time step calls each enabled module in every pass.
// Column suffixes _x, _y (, _z) of a vector probe (Module::probe_columns).
inline std::vector<std::string> axis_columns(int dim) {
  std::vector<std::string> c;
  for (int a = 0; a < dim; ++a) c.push_back(std::string("_") + "xyz"[a]);
  return c;
}

template <int D>
class Module {
 public:
  virtual ~Module() = default;
  virtual std::string name() const = 0;
  virtual void on_create(Simulation<D>&) {}  // fresh particles exist (not on restart)
  virtual void sums(Simulation<D>&) {}       // kernel sums at the new positions
  // An acoustic step of dual-criteria stepping: the kernel sums stay, the pair vectors moved;
  // refresh what must follow the positions (e.g. deformation gradients).
  virtual void acoustic_step(Simulation<D>&) {}
  virtual void rates(Simulation<D>&) {}             // rates from the half-step velocities
  virtual void drift(Simulation<D>&, double dt) {}  // integrate module state over dt
  virtual void constitutive(Simulation<D>&) {}      // per particle: EOS, stress
  virtual void forces(Simulation<D>&) {}            // add to the acceleration
  virtual void before_rebuild(Simulation<D>&) {}    // a rebuild follows (old list valid)
  virtual void diagnostics(Simulation<D>&) {}       // fields for output and probes only
  virtual void on_rebuild(Simulation<D>&) {}        // after a neighbour-list rebuild
  // After a restart's first rebuild, at the checkpoint's positions (Simulation::init(true)).
  virtual void restarted(Simulation<D>&) {}
  virtual void kicked(Simulation<D>&, double h) {}  // after every (half) kick of length h
  // Module state that is not a particle field, for checkpoints ("<module>.<key>" -> value).
  virtual void save_state(std::map<std::string, double>&) const {}
  virtual void load_state(Simulation<D>&, const std::map<std::string, double>&) {}
  virtual double max_dt(Simulation<D>&) { return std::numeric_limits<double>::infinity(); }
  // Multi-rate stepping (time_step.multi_rate, docs/theory.md): a fast module's passes and
  // max_dt concern only solid particles, which it integrates with sub-steps; its forces are
  // internal to solid bodies. Slow modules run once per (outer) step.
  virtual bool fast() const { return false; }
  // Probe types a module provides (e.g. "surface_force"): the column suffixes of `spec` ("_x",
  // "_y"... or ""), empty when the type is not this module's; `probe` appends one value per column.
  virtual std::vector<std::string> probe_columns(const ProbeSpec&) const { return {}; }
  // Whether the module's passes read the pair rows (Simulation::pairs) of the particles of body
  // b. Rows that no module reads stay empty during steps (the smallest distance of the guard is
  // still found); diagnostics and probes see complete rows.
  virtual bool reads_pair_rows(int /*body*/) const { return true; }
  virtual void probe(Simulation<D>&, const ProbeSpec&, std::vector<double>& out) {}
  // Elastic energy stored in the module's contacts now (Hertz or Lennard-Jones springs; not the
  // work dissipated by dashpots or friction): this rank's share, from its owned particles, so
  // that the sum over the ranks is the total (probes contact_energy and total_energy). Per metre
  // of depth in 2D. No collective call inside.
  virtual double potential_energy(Simulation<D>&) { return 0.0; }
};

// Pairs within the kernel support at the current positions, rebuilt with every force evaluation
// and valid until the next drift: for particle i, entries begin(i) <= k < end(i) hold the
// neighbour j, its periodic image (shift code), W(r) and F(r) = W'(r)/r, so that
// grad_i W_ij = F r. r = x_i - x_j is not stored: r(x, i, k) forms it from the positions, which
// do not change before the next drift (it is the same expression, so the same bits, as the one
// the list was built with). Every pair pass streams through j, code, w and f: 21 bytes per pair.
template <int D>
struct PairList {
  std::vector<std::size_t> first;  // n + 1 offsets (slots of the Verlet list)
  std::vector<int> count, j;
  std::vector<std::uint8_t> code;  // periodic image of j (Neighbours<D> shift code)
  std::array<Vec<D>, Neighbours<D>::kShifts> shift{};  // the shift vector of each code
  std::vector<double> w, f;
  std::size_t begin(std::size_t i) const { return first[i]; }
  std::size_t end(std::size_t i) const { return first[i] + count[i]; }
  // r_ij = x_i - x_j of the entries k of row i, periodic image included (x: the positions); a
  // Row holds x_i and the arrays in registers across a pair loop.
  struct Row {
    Vec<D> xi;
    const Vec<D>* x;
    const int* j;
    const std::uint8_t* code;
    const Vec<D>* shift;
    Vec<D> r(std::size_t k) const { return xi - x[j[k]] - shift[code[k]]; }
  };
  template <class X>
  Row row(const X& x, std::size_t i) const {
    return {x[i], x.data(), j.data(), code.data(), shift.data()};
  }
  template <class X>
  Vec<D> r(const X& x, std::size_t i, std::size_t k) const {
    return row(x, i).r(k);
  }
};

struct BodyInfo {
  std::string name;
  Phase phase;
  int material;
  double av_alpha, av_beta;           // artificial viscosity (MMB Eq. 17-18)
  double as_epsilon, as_n;            // artificial stress (MMB Eq. 19-20)
  double delta;                       // density diffusion (MMB Eq. 21)
  bool corrected_divergence = false;  // stress divergence with L_i (Bonet & Lok) or 1/S_i (MMB)
  int formulation = 0;                // 0 Eulerian (MMB), 2 non-hourglass (Zhang et al. 2024)
  bool total_lagrangian = false;      // formulation: total_lagrangian (Ganzenmueller 2015)
  double temperature = 0;             // initial temperature (K)
  int group = 0;  // interaction group: bodies of one continuum share it (-1 fluid, -2 walls,
                  // -3 rigid)
  std::array<double, 3> body_force{};  // acceleration on this body (the scene's unless given)
  double damping = 0;                  // mass-proportional damping rate [1/s]
  ParamMap params{};                   // each module's parameters (scene/module_keys.hpp)
};

// Wall time of each pass of a step, summed over the run (the slowest pass shows in summary.json).
struct PassClock {
  explicit PassClock(std::map<std::string, double>& acc) : acc_(acc) { restart(); }
  void restart() { t0_ = std::chrono::steady_clock::now(); }
  void lap(const char* pass) {
    const auto t = std::chrono::steady_clock::now();
    acc_[pass] += std::chrono::duration<double>(t - t0_).count();
    t0_ = t;
  }

 private:
  std::map<std::string, double>& acc_;
  std::chrono::steady_clock::time_point t0_;
};

template <int D>
class Simulation {
 public:
  using V = Vec<D>;
  explicit Simulation(Scene scene);

  // Fills bodies on the lattice and applies initial fields (fresh start).
  void create_particles();
  void add_module(std::unique_ptr<Module<D>> m) { modules_.push_back(std::move(m)); }
  // First neighbour build and force evaluation; with `restarted` the stored a, L... are kept.
  void init(bool restarted = false);
  // One kick-drift-kick step, shortened so as not to pass `stop`. Throws RunAborted (with a
  // diagnosis) if a guard trips.
  void advance(double stop = std::numeric_limits<double>::infinity());
  // Recomputes the pair list (PairList) and the volumes at the current state: needed after moving
  // particles or changing densities by hand (tests); a step does it itself.
  void update_pair_cache() { update_pair_cache(PairRows::all); }
  // Rebuilds the neighbour list now (before a checkpoint when checkpoint_rebuilds()).
  void rebuild_neighbours();
  // Restarts (restart.cpp). Every rebuild keeps its positions and densities as the fields
  // build_position and build_density, so that a restart on one rank without symmetry planes
  // rebuilds from them the list and reference data that rebuild made (bit-identical). A
  // checkpoint then needs no rebuild of its own, which the uninterrupted run would not have had;
  // runs with ghosts (ranks, mirror images: made at a rebuild, not in the checkpoint) or
  // dual-criteria stepping (its pair set is that of the last configuration update) still make one.
  bool checkpoint_rebuilds() const { return dec_ || mirror_ || scene_.advection_cfl > 0; }
  // During the restart's rebuild that restores the last one: on_rebuild finds the positions and
  // densities of then and keeps the state the checkpoint holds (reference configurations).
  bool restoring() const { return restoring_; }
  // State that is neither a particle field nor a module's ("sim.<key>" -> value).
  void save_state(std::map<std::string, double>& s) const;
  void load_state(const std::map<std::string, double>& s);
  // Diagnostic fields (e.g. the disorder measure) before output or probes.
  void diagnostics() {
    if (!listed_) return;  // a rebuild stopped half-way (a particle left the domain): no pairs
    if (skipped_rows_) update_pair_cache(PairRows::all);
    for (auto& m : modules_) m->diagnostics(*this);
  }

  // Accessors used by modules.
  Particles<D>& particles() { return p_; }
  const Scene& scene() const { return scene_; }
  const Kernel<D>& kernel() const { return kernel_; }
  const Neighbours<D>& neighbours() const { return nb_; }
  const std::vector<Material>& materials() const { return scene_.materials; }
  const std::vector<BodyInfo>& bodies() const { return bodies_; }
  const std::vector<std::unique_ptr<Module<D>>>& modules() const { return modules_; }
  double time() const { return t_; }
  double dt() const { return dt_; }
  double first_dt() const { return dt0_; }  // of the run's start (a restart: from its checkpoint)
  long step() const { return step_; }
  double dp() const { return scene_.dp; }
  const V& body_force() const { return g_; }
  // The body force of body b (the scene's, or the body's own `body_force`).
  V body_force(int b) const { return gb_[b]; }
  void set_state(double t, long step, double dt) { t_ = t, step_ = step, dt_ = dt; }

  // Smallest pair distance seen in the last force pass (set by the pair-force module).
  double min_distance() const { return min_r_; }
  // Pair-geometry and kernel-sum updates so far (every step unless dual-criteria time stepping).
  long configuration_updates() const { return configuration_updates_; }
  // Pairs within the support at the current positions (see PairList).
  const PairList<D>& pairs() const { return pairs_; }
  // Particle volumes V = m/rho, computed with the pair list (valid until the next drift).
  const std::vector<double>& volumes() const { return vol_; }
  // Interaction group of each particle: -1 for fluid (one continuum); for solids, the body or
  // the continuum several bodies share.
  const std::vector<int>& group() const { return group_; }
  // Reaction force of each boundary-condition set (force the constraint applies), last step.
  const std::vector<V>& reactions() const { return reactions_; }
  const std::vector<BoundarySpec>& boundaries() const { return scene_.boundaries; }
  // Removes the flagged particles at the next neighbour rebuild (forced; modules' before_rebuild
  // still sees them). Their mass is added to removed_mass() of their body, and what they carry
  // to removed(): "kinetic_energy" and the per-particle energy fields of kCarried.
  void remove_particles(const std::vector<char>& flag);
  const std::vector<double>& removed_mass() const { return removed_mass_; }
  static constexpr const char* kCarried[] = {"failure_energy", "hourglass_energy", "plastic_work"};
  // Sum over the removed particles of a body (all bodies if body < 0); 0 for an unknown name.
  double removed(const std::string& name, int body = -1) const;
  // Seconds spent in each pass of the steps so far: integration (kicks, drift), rates,
  // neighbours (rebuilds, MPI migration), pair_cache, sums, constitutive, forces, guards_and_dt.
  const std::map<std::string, double>& pass_seconds() const { return pass_seconds_; }
  // Multi-rate stepping: sub-steps of the solids in the last step (1 when single-rate).
  int substeps() const { return kappa_; }
  void set_substeps(int k) { kappa_ = k; }  // restart
  long total_substeps() const { return total_substeps_; }
  // "particle id 12 (body 'water') at (x, y)".
  std::string describe(std::size_t i);

  // Open MPI runs (see Decomposition): particles [0, owned()) belong to this rank, the rest are
  // ghost copies, which have no neighbour list. Loops that write a particle's own values may run
  // over all; sums over
  // particles (forces on bodies, probes, energies) take the owned ones and reduce over comm().
  const Comm& comm() const { return comm_; }
  // Mirror images (domain.mirror, see Mirror) are ghosts too: they follow the owned particles.
  std::size_t owned() const {
    return dec_ ? dec_->owned() : mirror_ ? mirror_->owned() : p_.size();
  }
  const Decomposition<D>* decomposition() const { return dec_.get(); }
  // Refreshes ghost copies of fields a pass has just written (a no-op on one rank). Pair loops
  // leave ghosts without valid sums (they have no list): a field read through neighbours later,
  // or used by a ghost's own per-particle update, must be exchanged by the pass that wrote it.
  void exchange(std::initializer_list<int> fields) {
    if (dec_) dec_->exchange(p_, std::span<const int>(fields.begin(), fields.size()));
    if (mirror_) mirror_->exchange(p_, std::span<const int>(fields.begin(), fields.size()));
  }
  // The particles p holds now are this rank's own (its share of a checkpoint just read): the
  // first rebuild balances the ranks.
  void adopt_particles() {
    if (dec_) dec_->adopt(p_);
    if (mirror_) mirror_->adopt(p_);
  }

 private:
  void fill_bodies();  // create_particles without the modules' hooks
  void kick(double h, double t_bc);
  void newmark_kick(double dt);  // second kick with time_step.newmark_gamma (docs/theory.md)
  void keep_acceleration();      // a_n for the first Newmark step

  void drift(double dt);
  // Multi-rate stepping (multi_rate.cpp).
  void init_multi_rate();
  void advance_multi_rate(double stop);
  void substep(double ds, double dt, bool last);
  void drift_positions(double dt, bool solids, double weight);
  template <class Reset>
  void module_forces(bool fast, Reset reset);
  void fast_forces(double weight);
  void add_fast_acceleration();
  void slow_forces();
  void slow_rates(double dt);
  double compute_dt_multi_rate();
  void compute_reactions();
  void check_dt_collapse() const;  // throws RunAborted
  void body_acceleration();        // a = body force - damping
  bool update_neighbours();        // true when the lists were rebuilt
  void set_loop_schedule() const;  // dynamic chunks for the schedule(runtime) loops
  void keep_build_state();         // positions and densities of the rebuild just made
  void restore_build_state();      // the restart's rebuild, at the last rebuild's state
  void flag_pending_removals();    // the checkpoint's removals for the next rebuild
  // Rows of the pair list to fill: those a module reads, of those only the solids' (multi-rate
  // sub-steps), or all (diagnostics, probes, tests).
  enum class PairRows { read, read_solids, all };
  void update_pair_cache(PairRows rows);
  // configuration: recompute the pair geometry and the kernel sums (always, unless dual-criteria
  // time stepping keeps them for the acoustic steps of an advection step).
  void compute_forces(bool configuration = true);
  double compute_dt();
  double max_speed();           // largest |v| over all ranks
  void refresh_pair_vectors();  // dual-criteria acoustic step: r_ij only
  void check_guards();
  void apply_bc_velocity(double t);

  Scene scene_;
  const Comm& comm_ = Comm::world();
  std::unique_ptr<Decomposition<D>> dec_;
  std::unique_ptr<Mirror<D>> mirror_;  // domain.mirror (serial runs only)
  Particles<D> p_;
  Kernel<D> kernel_;
  Neighbours<D> nb_;
  std::vector<BodyInfo> bodies_;
  std::vector<std::unique_ptr<Module<D>>> modules_;
  std::vector<std::vector<Expression>> bc_velocity_;
  std::vector<V> reactions_;
  int kaprev_ = -1;  // field a_n for the Newmark gamma correction (only when gamma != 0.5)
  std::vector<char> remove_flag_;                       // pending removal (remove_particles)
  std::vector<double> removed_mass_;                    // per body
  std::map<std::string, std::vector<double>> removed_;  // per quantity, per body (removed())
  void account_removed(const std::vector<char>& flag);
  int kbc_ = -1;  // field "boundary" (1 + index of the boundary condition, 0 = free)
  V g_;
  std::vector<V> gb_;            // per body
  std::vector<double> damping_;  // per body: mass-proportional damping rate [1/s]
  bool damped_ = false;
  double t_ = 0, dt_ = 0, dt0_ = 0;
  bool listed_ = false;          // the neighbour list and pair cache fit the particles
  double t_configuration_ = -1;  // dual-criteria: time of the next configuration update
  long configuration_updates_ = 0;
  long step_ = 0;
  double min_r_ = 0;
  PairList<D> pairs_;
  std::vector<double> rmin_, vol_;
  std::vector<double> rmin_build_;  // rmin_ at the first fill after the last rebuild
  int rmin_build_of_ = -1;          // the build it belongs to (Neighbours::builds)
  std::vector<double> wave_speed_;  // per material, sqrt((K + 4 mu/3)/rho0)
  std::vector<int> group_, jmin_;
  long min_i_ = -1, min_j_ = -1;
  bool rebuild_requested_ = false;
  // Fields build_position and build_density; the restart's rebuild that restores them; what the
  // checkpoint held (load_state): a build state, the rebuilds so far, pending removals (ids).
  int kxb_ = -1, krb_ = -1;
  bool restoring_ = false, restore_ = false, rebuild_pending_ = false;
  int builds_before_ = 0;
  std::vector<std::int64_t> pending_ids_;
  std::vector<char> read_rows_;  // per body: a module reads its pair rows (reads_pair_rows)
  bool skipped_rows_ = false;    // some body's rows are left empty during steps
  // Multi-rate: fields a_slow (all), a_fast and the mean velocity and acceleration over the
  // step (solids); sub-steps per step.
  int kas_ = -1, kaf_ = -1, kvb_ = -1, kab_ = -1, kappa_ = 1;
  long total_substeps_ = 0;
  std::map<std::string, double> pass_seconds_;
};

}  // namespace monosph
