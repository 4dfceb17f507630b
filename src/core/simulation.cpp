#include "core/simulation.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <unordered_map>

namespace monosph {

template <int D>
Simulation<D>::Simulation(Scene scene) : scene_(std::move(scene)) {
  if (scene_.dimension != D) throw std::logic_error("scene dimension mismatch");
  kernel_ = Kernel<D>(scene_.kernel, scene_.h());
  Domain<D> dom;
  for (int a = 0; a < D; ++a) {
    dom.lo[a] = scene_.domain_min[a];
    dom.hi[a] = scene_.domain_max[a];
    dom.periodic[a] = scene_.periodic[a];
  }
  if (scene_.has_mirror()) {
    if (comm_.parallel())
      throw InputError("domain.mirror: not supported on more than one MPI rank");
    if (scene_.multi_rate) throw InputError("time_step.multi_rate: not with domain.mirror");
    const double halo = kernel_.radius() + scene_.skin_factor * scene_.h();
    mirror_ = std::make_unique<Mirror<D>>(dom, scene_.mirror_min, scene_.mirror_max, halo);
    dom = mirror_->extended(dom);  // the images lie beyond the planes
  }
  nb_.configure(dom, kernel_.radius(), scene_.skin_factor * scene_.h());
  if (comm_.parallel())
    dec_ = std::make_unique<Decomposition<D>>(comm_, dom, nb_.cutoff() + nb_.skin());
  std::vector<std::string> continua;
  for (const auto& b : scene_.bodies) {
    int g = b.phase == "fluid" ? -1 : b.phase == "rigid" ? -3 : -2;
    if (b.phase == "solid") {
      auto it = std::find(continua.begin(), continua.end(), b.continuum);
      g = static_cast<int>(it - continua.begin());
      if (it == continua.end()) continua.push_back(b.continuum);
    }
    const Phase ph = b.phase == "fluid"   ? kFluid
                     : b.phase == "wall"  ? kWall
                     : b.phase == "rigid" ? kRigid
                                          : kSolid;
    BodyInfo info{b.name, ph, b.material, b.av_alpha, b.av_beta, b.as_epsilon, b.as_n, b.delta};
    info.corrected_divergence = b.corrected_divergence;
    info.formulation = b.formulation;
    info.total_lagrangian = b.total_lagrangian;
    info.temperature = b.temperature;
    info.group = g;
    info.damping = b.damping;
    info.params = b.params;
    const Point& bf = b.body_force.empty() ? scene_.body_force : b.body_force;
    for (int a = 0; a < D; ++a) info.body_force[a] = bf[a];
    bodies_.push_back(std::move(info));
  }
  removed_mass_.assign(bodies_.size(), 0.0);
  set_loop_schedule();
  kxb_ = p_.add_field("build_position", D);  // the state of the last rebuild (restart.cpp)
  krb_ = p_.add_field("build_density", 1);
  if (scene_.newmark_gamma != 0.5) kaprev_ = p_.add_field("previous_acceleration", D);
  if (scene_.multi_rate) {  // multi_rate.cpp
    kas_ = p_.add_field("slow_acceleration", D);
    kaf_ = p_.add_field("fast_acceleration", D);
    kvb_ = p_.add_field("mean_velocity", D);
    kab_ = p_.add_field("mean_fast_acceleration", D);
  }
  for (int a = 0; a < D; ++a) g_[a] = scene_.body_force[a];
  for (const auto& b : bodies_) gb_.push_back(Eigen::Map<const V>(b.body_force.data()));
  for (const auto& b : bodies_) damping_.push_back(b.damping), damped_ = damped_ || b.damping > 0;
  for (const auto& m : scene_.materials) wave_speed_.push_back(m.wave_speed());
  if (!scene_.boundaries.empty()) {
    kbc_ = p_.add_field("boundary", 1, FieldType::Int, false);
    for (std::size_t k = 0; k < scene_.boundaries.size(); ++k) {
      const auto& bc = scene_.boundaries[k];
      std::vector<Expression> ex;
      for (int a = 0; a < static_cast<int>(bc.velocity_expr.size()); ++a)
        if (bc.velocity_expr[a] == "free")  // an empty expression: the component moves freely
          ex.emplace_back();
        else
          ex.emplace_back(bc.velocity_expr[a],
                          "boundary_conditions[" + std::to_string(k) + "].velocity",
                          scene_.variables);
      bc_velocity_.push_back(std::move(ex));
    }
    reactions_.assign(scene_.boundaries.size(), V::Zero());
  }
}

template <int D>
std::string Simulation<D>::describe(std::size_t i) {
  std::ostringstream os;
  os.precision(6);
  os << "particle id " << p_.id()[i] << " (body '" << bodies_[p_.body()[i]].name << "') at (";
  for (int a = 0; a < D; ++a) os << (a ? ", " : "") << p_.x()[i][a];
  os << ")";
  return os.str();
}

template <int D>
void Simulation<D>::set_loop_schedule() const {
  // Physics loops use schedule(runtime): dynamic chunks of about 1/32 of the owned particles, so
  // that neither phase blocks nor a slower vCPU leave a thread waiting (docs/performance.md, issue
  // 25). The loops gather per particle and reduce only integers, max, min: same bits on any count.
  const long chunk = std::clamp(static_cast<long>(owned()) / 32, 64L, 2048L);
  omp_set_schedule(omp_sched_dynamic, static_cast<int>(chunk));
}

template <int D>
bool Simulation<D>::update_neighbours() {
  bool need = rebuild_requested_ || nb_.needs_rebuild(p_);
  if (dec_) need = comm_.max(long(need)) > 0;
  if (!need) return false;
  listed_ = false;
  rebuild_requested_ = false;
  // Restoring the last rebuild (restart.cpp): the particles are in its order already.
  const bool reorder =
      !restoring_ && scene_.reorder_every > 0 && nb_.builds() % scene_.reorder_every == 0;
  if (!restoring_)
    for (auto& m : modules_) m->before_rebuild(*this);
  const std::size_t own = owned();
  std::vector<float> work;  // MPI: cost of each owned particle, for the balance
  if (mirror_) {            // images are made anew below
    mirror_->drop(p_);
    if (remove_flag_.size() > own) remove_flag_.resize(own);
  }
  if (dec_) {  // ghosts are made anew below
    p_.resize(own);
    if (remove_flag_.size() > own) remove_flag_.resize(own);
    // Pair loops dominate a step: a particle costs about 1 + its pairs in the support.
    work.assign(own, 1.0f);
    if (pairs_.count.size() >= own)
      for (std::size_t i = 0; i < own; ++i) work[i] += static_cast<float>(pairs_.count[i]);
  }
  if (!remove_flag_.empty() || dec_) {  // with MPI every rank joins the mass reduction
    const auto& flag = remove_flag_;
    account_removed(flag);
    if (!remove_flag_.empty()) {
      if (dec_) std::erase_if(work, [&, i = std::size_t(0)](float) mutable { return flag[i++]; });
      p_.remove(remove_flag_);
    }
    remove_flag_.clear();
  }
  long bad;
  if (dec_) {
    bad = nb_.wrap(p_);
    std::string msg;
    if (bad >= 0) {
      std::ostringstream os;
      os << describe(bad) << " left the domain at t = " << t_;
      msg = os.str();
    }
    msg = comm_.first_message(msg);
    if (!msg.empty()) throw RunAborted(msg);
    dec_->migrate(p_, work);
    if (reorder) nb_.sort_by_cell(p_);
    dec_->make_ghosts(p_);
    bad = nb_.build(p_, false, dec_->owned());
  } else if (mirror_) {
    bad = nb_.wrap(p_);
    if (bad < 0) {
      if (reorder) nb_.sort_by_cell(p_);
      mirror_->make_ghosts(p_);
      bad = nb_.build(p_, false, mirror_->owned());
    }
  } else {
    bad = nb_.build(p_, reorder);
  }
  if (bad >= 0) {
    std::ostringstream os;
    os << describe(bad) << " left the domain at t = " << t_;
    throw RunAborted(os.str());
  }
  set_loop_schedule();
  keep_build_state();
  for (auto& m : modules_) m->on_rebuild(*this);
  listed_ = true;
  return true;
}

template <int D>
void Simulation<D>::remove_particles(const std::vector<char>& flag) {
  if (remove_flag_.empty()) remove_flag_.assign(p_.size(), 0);
  for (std::size_t i = 0; i < flag.size() && i < remove_flag_.size(); ++i)
    remove_flag_[i] = remove_flag_[i] || flag[i];
  rebuild_requested_ = true;
}

template <int D>
void Simulation<D>::rebuild_neighbours() {
  rebuild_requested_ = true;
  update_neighbours();
  update_pair_cache(PairRows::all);  // pairs_/group_ are indexed by the list just rebuilt
}

template <int D>
void Simulation<D>::apply_bc_velocity(double t) {
  if (kbc_ < 0) return;
  auto bc = p_.template view<std::int64_t>(kbc_);
  auto v = p_.v();
  auto x = p_.x();
  const std::size_t n = p_.size();
  // Fixed sets in parallel; expressions (muparser is not thread-safe) on one thread.
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i)
    if (bc[i] && bc_velocity_[bc[i] - 1].empty()) v[i].setZero();
  bool any_expr = false;
  for (const auto& e : bc_velocity_) any_expr = any_expr || !e.empty();
  if (!any_expr) return;
  for (std::size_t i = 0; i < n; ++i) {
    if (!bc[i] || bc_velocity_[bc[i] - 1].empty()) continue;
    const auto& ex = bc_velocity_[bc[i] - 1];
    const double zz = D == 3 ? x[i][D - 1] : 0.0;
    for (int a = 0; a < D; ++a)
      if (!ex[a].empty()) v[i][a] = ex[a](x[i][0], x[i][1], zz, t);
  }
}

template <int D>
void Simulation<D>::kick(double h, double t_bc) {
  auto v = p_.v();
  auto a = p_.a();
  const std::size_t n = p_.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) v[i] += h * a[i];
  apply_bc_velocity(t_bc);
  for (auto& m : modules_) m->kicked(*this, h);
}

template <int D>
void Simulation<D>::newmark_kick(double dt) {
  // Second kick of explicit Newmark (beta = 0): with the first half kick already applied,
  // v += dt (gamma a_{n+1} - (gamma - 1/2) a_n); a_{n+1} is kept as the next step's a_n.
  const double g = scene_.newmark_gamma;
  auto v = p_.v();
  auto a = p_.a();
  auto ap = p_.template view<V>(kaprev_);
  const std::size_t n = p_.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    v[i] += dt * (g * a[i] - (g - 0.5) * ap[i]);
    ap[i] = a[i];
  }
  apply_bc_velocity(t_);
  for (auto& m : modules_) m->kicked(*this, 0.5 * dt);
}

template <int D>
void Simulation<D>::keep_acceleration() {
  if (kaprev_ < 0) return;
  auto a = p_.a();
  auto ap = p_.template view<V>(kaprev_);
  std::copy(a.begin(), a.end(), ap.begin());
}

template <int D>
void Simulation<D>::drift(double dt) {
  auto x = p_.x();
  auto v = p_.v();
  auto rho = p_.rho();
  auto drho = p_.drho();
  const std::size_t n = p_.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    x[i] += dt * v[i];
    rho[i] += dt * drho[i];
  }
  for (auto& m : modules_) m->drift(*this, dt);
}

template <int D>
void Simulation<D>::refresh_pair_vectors() {
  // Acoustic step of dual-criteria time stepping: the pair vectors r_ij follow the particles (the
  // forces act along the current directions) and so do the kernel values and factors unless
  // `kernel: frozen`; the pair set and the kernel sums stay those of the last configuration
  // update, and so does the smallest pair distance that the min-distance guard checks. (Frozen
  // kernel factors with moving r_ij change the stiffness of the Eulerian hourglass-controlled
  // plate: it bends 20 % too far and leaves the domain; measured in cases/oscillating_plate.)
  if (scene_.frozen_kernel) return;  // r_ij is formed from the positions where it is used
  auto x = p_.x();
  const std::size_t n = p_.size();
  auto& pl = pairs_;
  const Kernel<D> W = kernel_;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t q = pl.first[i]; q < pl.first[i] + pl.count[i]; ++q)
      W.wf(pl.r(x, i, q).squaredNorm(), pl.w[q], pl.f[q]);
}

template <int D>
void Simulation<D>::update_pair_cache(PairRows rows) {
  auto x = p_.x();
  auto ph = p_.phase();
  auto bd = p_.body();
  auto m = p_.m();
  auto rho = p_.rho();
  const std::size_t n = p_.size();
  const double rs2 = kernel_.radius() * kernel_.radius();
  const Kernel<D> W = kernel_;  // a local copy: the stores below cannot alias its parameters
  auto& pl = pairs_;
  pl.first.resize(n + 1);
  pl.count.resize(n);
  pl.j.resize(nb_.pairs());
  pl.code.resize(nb_.pairs());
  pl.w.resize(nb_.pairs());
  pl.f.resize(nb_.pairs());
  group_.resize(n);
  vol_.resize(n);
  rmin_.resize(n);
  jmin_.resize(n);
  const bool cubic = W.type() == KernelType::CubicSpline;
  // Raw pointers held in registers: stores through the pair arrays cannot alias them.
  std::size_t* __restrict first = pl.first.data();
  int* __restrict cnt = pl.count.data();
  int* __restrict pj = pl.j.data();
  std::uint8_t* __restrict pc = pl.code.data();
  double* __restrict pw = pl.w.data();
  double* __restrict pf = pl.f.data();
  const V* __restrict xs = x.data();
  const Neighbours<D>& nb = nb_;
  const int* __restrict nbr = nb.nbr_data();
  const std::uint8_t* __restrict code = nb.code_data();
  const std::array<V, Neighbours<D>::kShifts> shift = nb.shifts();
  pl.shift = shift;
  const bool all = rows == PairRows::all;
  const char* read = read_rows_.data();
  // An unread row only serves the guard. Between rebuilds every particle stays within skin/2 of
  // its place at the build, so a distance changes by less than a skin from the build to any
  // moment before the next one: a row whose smallest distance at its first fill after the build
  // exceeded the guard's limit + 2 skins cannot reach the limit before the next rebuild and is
  // not revisited (its rmin_ stays; complete rows for probes come from diagnostics).
  const bool bound = rmin_build_of_ == nb_.builds();
  const bool fresh = !bound && rows != PairRows::read_solids;
  const double far = scene_.min_distance * scene_.dp + 2 * nb_.skin();
  const double* rb = rmin_build_.data();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    group_[i] = bodies_[bd[i]].group;  // of every row: a rebuild may have reordered
    vol_[i] = m[i] / rho[i];
    if (rows == PairRows::read_solids && ph[i] != kSolid) continue;  // a multi-rate sub-step
    double best = std::numeric_limits<double>::infinity();
    int jb = -1;
    const std::size_t k0 = nb.begin(i), k1 = nb.end(i);
    std::size_t q = k0;
    first[i] = q;
    const V xi = xs[i];
    if (!all && !read[bd[i]]) {  // a row no module reads: the guard's smallest distance only
      cnt[i] = 0;
      if (bound && rb[i] > far) continue;
      for (std::size_t k = k0; k < k1; ++k) {
        const double r2 = (xi - xs[nbr[k]] - shift[code[k]]).squaredNorm();
        if (r2 < best) best = r2, jb = nbr[k];
      }
      rmin_[i] = std::sqrt(best);
      jmin_[i] = jb;
      continue;
    }
    for (std::size_t k = k0; k < k1; ++k) {
      const int j = nbr[k];
      const V r = xi - xs[j] - shift[code[k]];
      const double r2 = r.squaredNorm();
      if (r2 < best) best = r2, jb = j;
      // Branch-free compaction: the slot is written always and kept if inside the support.
      pj[q] = j;
      pc[q] = code[k];
      pw[q] = r2;
      q += r2 < rs2;
    }
    // Kernel values of the kept pairs in a dense loop (the compiler vectorises the root and
    // the division, the slowest part, when the kernel is the branch-free cubic spline).
    if (cubic) {
      for (std::size_t k = k0; k < q; ++k) W.wf_cubic(pw[k], pw[k], pf[k]);
    } else {
      for (std::size_t k = k0; k < q; ++k) W.wf(pw[k], pw[k], pf[k]);
    }
    cnt[i] = static_cast<int>(q - k0);
    rmin_[i] = std::sqrt(best);
    jmin_[i] = jb;
  }
  pl.first[n] = nb_.pairs();
  if (fresh) rmin_build_ = rmin_, rmin_build_of_ = nb_.builds();
  min_r_ = std::numeric_limits<double>::infinity();
  min_i_ = min_j_ = -1;
  const std::size_t own = owned();
  for (std::size_t i = 0; i < own; ++i)
    if (rmin_[i] < min_r_) min_r_ = rmin_[i], min_i_ = static_cast<long>(i), min_j_ = jmin_[i];
}

template <int D>
void Simulation<D>::compute_forces(bool configuration) {
  PassClock clock(pass_seconds_);
  if (configuration) {  // else: an acoustic step of dual-criteria time stepping
    update_pair_cache(PairRows::read);
    clock.lap("pair_cache");
    for (auto& m : modules_) m->sums(*this);
    clock.lap("sums");
    ++configuration_updates_;
  } else {
    refresh_pair_vectors();
    clock.lap("pair_cache");
    for (auto& m : modules_) m->acoustic_step(*this);
    clock.lap("sums");
  }
  for (auto& m : modules_) m->constitutive(*this);
  clock.lap("constitutive");
  body_acceleration();
  for (auto& m : modules_) m->forces(*this);
  exchange({p_.find("acceleration")});  // ghosts then kick and drift as their owners do
  clock.lap("forces");
  compute_reactions();
}

template <int D>
void Simulation<D>::body_acceleration() {
  // Body force, and mass-proportional damping a -= c v on the particles without a prescribed
  // path (one pass; c = 0 for undamped bodies).
  auto a = p_.a();
  auto bd = p_.body();
  auto v = p_.v();
  const std::size_t n = p_.size();
  const std::int64_t* bc = kbc_ >= 0 ? p_.template view<std::int64_t>(kbc_).data() : nullptr;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    a[i] = gb_[bd[i]];
    if (damped_ && (!bc || !bc[i])) a[i] -= damping_[bd[i]] * v[i];
  }
}

template <int D>
void Simulation<D>::compute_reactions() {
  // Reaction of each constrained set: what holds it on its prescribed path.
  if (kbc_ < 0) return;
  auto a = p_.a();
  auto bc = p_.template view<std::int64_t>(kbc_);
  auto mass = p_.m();
  for (auto& r : reactions_) r.setZero();
  const std::size_t own = owned();
  for (std::size_t i = 0; i < own; ++i)
    if (bc[i]) {
      const auto& ex = bc_velocity_[bc[i] - 1];
      for (int c = 0; c < D; ++c)  // a free component has no reaction
        if (ex.empty() || !ex[c].empty()) reactions_[bc[i] - 1][c] -= mass[i] * a[i][c];
    }
  if (dec_)
    for (auto& r : reactions_) comm_.sum(std::span<double>(r.data(), D));
}

template <int D>
double Simulation<D>::max_speed() {
  auto v = p_.v();
  const std::size_t n = owned();
  double vmax = 0;
#pragma omp parallel for reduction(max : vmax) schedule(static)
  for (std::size_t i = 0; i < n; ++i) vmax = std::max(vmax, v[i].norm());
  return comm_.max(vmax);
}

template <int D>
double Simulation<D>::compute_dt() {
  auto v = p_.v();
  auto a = p_.a();
  auto mt = p_.material();
  auto ph = p_.phase();
  const std::size_t n = owned();
  const double h = kernel_.h();
  const auto& c = wave_speed_;
  double dt_ac = std::numeric_limits<double>::infinity(), dt_f = dt_ac;
#pragma omp parallel for reduction(min : dt_ac, dt_f) schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    // Rigid-cluster particles carry no waves: only their speed counts.
    dt_ac = std::min(dt_ac, h / ((ph[i] == kRigid ? 0.0 : c[mt[i]]) + v[i].norm()));
    const double an = a[i].norm();
    if (an > 0) dt_f = std::min(dt_f, std::sqrt(h / an));
  }
  // Zhang et al. 2024, Eq. 22: the acoustic step of dual-criteria time stepping.
  const double cfl = scene_.advection_cfl > 0 ? scene_.acoustic_cfl : scene_.cfl;
  double dt = std::min(cfl * dt_ac, scene_.force_factor * dt_f);
  for (auto& m : modules_) dt = std::min(dt, m->max_dt(*this));
  if (scene_.max_dt > 0) dt = std::min(dt, scene_.max_dt);
  return comm_.min(dt);
}

template <int D>
void Simulation<D>::advance(double stop) {
  if (scene_.multi_rate) return advance_multi_rate(stop);
  // Approach `stop` in at most two equal steps so that no sliver of a step is left.
  const double rest = stop - t_;
  const double dt = rest <= dt_ ? rest : rest < 2 * dt_ ? 0.5 * rest : dt_;
  PassClock clock(pass_seconds_);
  kick(0.5 * dt, t_ + 0.5 * dt);
  clock.lap("integration");
  for (auto& m : modules_) m->rates(*this);
  clock.lap("rates");
  drift(dt);
  t_ += dt;
  ++step_;
  clock.lap("integration");
  const bool rebuilt = update_neighbours();
  clock.lap("neighbours");
  // Dual-criteria time stepping (Zhang et al. 2024, Sect. 5): the configuration is updated once
  // per advection step CFL_ad h / |v|max (and after every neighbour rebuild); the acoustic steps
  // between keep the pair geometry and kernel sums of the last update.
  const bool configuration = scene_.advection_cfl <= 0 || rebuilt || t_ >= t_configuration_;
  compute_forces(configuration);  // times its own passes
  if (configuration && scene_.advection_cfl > 0) {
    const double vmax = max_speed();
    t_configuration_ = vmax > 0 ? t_ + scene_.advection_cfl * kernel_.h() / vmax : t_;
  }
  clock.restart();
  if (kaprev_ >= 0)
    newmark_kick(dt);
  else
    kick(0.5 * dt, t_);
  clock.lap("integration");
  check_guards();
  dt_ = compute_dt();
  clock.lap("guards_and_dt");
  check_dt_collapse();
}

template <int D>
void Simulation<D>::check_dt_collapse() const {
  if (dt_ >= scene_.dt_collapse * dt0_) return;
  std::ostringstream os;
  os << "time step collapsed to " << dt_ << " s (initial " << dt0_ << " s) at t = " << t_;
  throw RunAborted(os.str());
}

template <int D>
void Simulation<D>::check_guards() {
  auto x = p_.x();
  auto v = p_.v();
  auto rho = p_.rho();
  auto mt = p_.material();
  const std::size_t n = owned();
  long bad = -1;
  int why = 0;  // 1 non-finite, 2 too fast
#pragma omp parallel for schedule(static) reduction(max : bad)
  for (std::size_t i = 0; i < n; ++i) {
    if (!x[i].allFinite() || !v[i].allFinite() || !std::isfinite(rho[i]))
      bad = std::max(bad, long(i));
  }
  if (bad >= 0) why = 1;
  if (!why) {
    long fast = std::numeric_limits<long>::max();
#pragma omp parallel for schedule(static) reduction(min : fast)
    for (std::size_t i = 0; i < n; ++i)
      if (v[i].norm() > scene_.max_mach * wave_speed_[mt[i]]) fast = std::min(fast, long(i));
    if (fast != std::numeric_limits<long>::max()) bad = fast, why = 2;
  }
  std::ostringstream os;
  os.precision(6);
  if (why == 1) {
    os << "non-finite state (position, velocity or density) at " << describe(bad) << ", t = " << t_;
  } else if (why == 2) {
    os << describe(bad) << " moves at " << v[bad].norm() << " m/s, above " << scene_.max_mach
       << " of its wave speed " << scene_.materials[mt[bad]].wave_speed() << " m/s, at t = " << t_;
  } else if (min_i_ >= 0 && min_r_ < scene_.min_distance * scene_.dp) {
    os << describe(min_i_) << " and particle id " << p_.id()[min_j_] << " are "
       << min_r_ / scene_.dp << " dp apart (limit " << scene_.min_distance << " dp) at t = " << t_;
  }
  // All ranks stop together with the message of the lowest rank that saw a problem.
  const std::string msg = dec_ ? comm_.first_message(os.str()) : os.str();
  if (!msg.empty()) throw RunAborted(msg);
}

template class Simulation<2>;
template class Simulation<3>;

}  // namespace monosph
