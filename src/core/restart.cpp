// The first neighbour build of a run, fresh or restarted, and the state a checkpoint keeps so
// that a restart continues the run bit for bit on one rank (README, "Stopping, restarting"):
// the positions and densities of the last neighbour rebuild (fields build_position and
// build_density), the number of rebuilds so far (the re-sorting period counts them), the
// initial time step (the collapse guard's reference), the particles flagged for removal at the
// next rebuild, the time of the next configuration update of dual-criteria stepping, and what
// removed particles took along (mass, energies: removed()).
#include <fmt/format.h>

#include <algorithm>
#include <charconv>

#include "core/simulation.hpp"

namespace monosph {

template <int D>
void Simulation<D>::init(bool restarted) {
  read_rows_.assign(bodies_.size(), 0);
  for (std::size_t b = 0; b < bodies_.size(); ++b)
    for (const auto& m : modules_) read_rows_[b] = read_rows_[b] || m->reads_pair_rows(int(b));
  skipped_rows_ = std::find(read_rows_.begin(), read_rows_.end(), 0) != read_rows_.end();
  if (restarted) {
    // Ghosts (ranks, mirror images) are made at a rebuild from the current positions: such a
    // run's checkpoints were written right after a rebuild, which it repeats here.
    if (restore_ && !dec_ && !mirror_) {
      restore_build_state();
    } else {
      rebuild_requested_ = true;
      update_neighbours();
    }
    if (restore_) nb_.set_builds(builds_before_);  // the re-sorting period counts on
    flag_pending_removals();
    for (auto& m : modules_) m->restarted(*this);
    update_pair_cache(PairRows::read);
    if (dt_ <= 0) dt_ = scene_.multi_rate ? compute_dt_multi_rate() : compute_dt();
    if (dt0_ <= 0) dt0_ = dt_;  // a checkpoint of an earlier version
    keep_acceleration();
    return;
  }
  rebuild_requested_ = true;
  update_neighbours();
  apply_bc_velocity(t_);
  if (scene_.multi_rate) return init_multi_rate();
  compute_forces();
  keep_acceleration();
  check_guards();
  dt_ = compute_dt();
  dt0_ = dt_;
}

template <int D>
void Simulation<D>::keep_build_state() {
  if (restoring_) return;  // the fields hold the current state then (restore_build_state)
  auto x = p_.x();
  auto rho = p_.rho();
  auto xb = p_.template view<V>(kxb_);
  auto rb = p_.template view<double>(krb_);
  const std::size_t n = owned();
  std::copy(x.begin(), x.begin() + n, xb.begin());
  std::copy(rho.begin(), rho.begin() + n, rb.begin());
}

template <int D>
void Simulation<D>::restore_build_state() {
  // The last rebuild once more, at its own positions (wrapped then) and densities: the same
  // Verlet list, displacement reference and the modules' reference data (the solids' reference
  // configuration, MMB Eq. 30); the particles are in that rebuild's order (no re-sort).
  auto exchange_state = [&] {
    auto x = p_.x();
    auto rho = p_.rho();
    auto xb = p_.template view<V>(kxb_);
    auto rb = p_.template view<double>(krb_);
    std::swap_ranges(x.begin(), x.end(), xb.begin());
    std::swap_ranges(rho.begin(), rho.end(), rb.begin());
  };
  exchange_state();
  restoring_ = rebuild_requested_ = true;
  update_neighbours();
  restoring_ = false;
  exchange_state();
}

template <int D>
void Simulation<D>::flag_pending_removals() {
  // Removals flagged before the checkpoint happen at the next rebuild, as they would have.
  rebuild_requested_ = rebuild_pending_;
  if (pending_ids_.empty()) return;
  std::sort(pending_ids_.begin(), pending_ids_.end());
  auto id = p_.id();
  remove_flag_.assign(p_.size(), 0);
  for (std::size_t i = 0; i < p_.size(); ++i)
    remove_flag_[i] = std::binary_search(pending_ids_.begin(), pending_ids_.end(), id[i]);
}

template <int D>
void Simulation<D>::account_removed(const std::vector<char>& flag) {
  // Mass, kinetic energy and the carried energies of the particles leaving (summed over ranks).
  auto bd = p_.body();
  auto m = p_.m();
  auto v = p_.v();
  const std::size_t nb = removed_mass_.size();
  std::vector<std::pair<std::string, int>> fields{{"mass", -1}, {"kinetic_energy", -1}};
  for (const char* name : kCarried)
    if (p_.find(name) >= 0) fields.emplace_back(name, p_.find(name));
  std::vector<double> sum(fields.size() * nb, 0.0);
  for (std::size_t i = 0; i < flag.size() && i < p_.size(); ++i) {
    if (!flag[i]) continue;
    sum[bd[i]] += m[i];
    sum[nb + bd[i]] += 0.5 * m[i] * v[i].squaredNorm();
    for (std::size_t f = 2; f < fields.size(); ++f)
      sum[f * nb + bd[i]] += p_.field(fields[f].second).real[i];
  }
  comm_.sum(sum);
  for (std::size_t b = 0; b < nb; ++b) removed_mass_[b] += sum[b];
  for (std::size_t f = 1; f < fields.size(); ++f) {
    auto& r = removed_[fields[f].first];
    r.resize(nb, 0.0);
    for (std::size_t b = 0; b < nb; ++b) r[b] += sum[f * nb + b];
  }
}

template <int D>
double Simulation<D>::removed(const std::string& name, int body) const {
  const auto it = removed_.find(name);
  if (name != "mass" && it == removed_.end()) return 0.0;
  const std::vector<double>& r = name == "mass" ? removed_mass_ : it->second;
  double sum = 0;
  for (std::size_t b = 0; b < r.size(); ++b)
    if (body < 0 || int(b) == body) sum += r[b];
  return sum;
}

template <int D>
void Simulation<D>::save_state(std::map<std::string, double>& s) const {
  // What removed particles took along (removed()): sums over all ranks, the same on each.
  for (std::size_t b = 0; b < removed_mass_.size(); ++b)
    if (removed_mass_[b] != 0) s[fmt::format("sim.removed.mass.{}", b)] = removed_mass_[b];
  for (const auto& [name, r] : removed_)
    for (std::size_t b = 0; b < r.size(); ++b)
      if (r[b] != 0) s[fmt::format("sim.removed.{}.{}", name, b)] = r[b];
  s["sim.builds"] = nb_.builds();
  s["sim.dt0"] = dt0_;
  if (scene_.advection_cfl > 0) s["sim.t_configuration"] = t_configuration_;
  if (rebuild_requested_) s["sim.rebuild_requested"] = 1;
  const auto& id = p_.field("id").ints;
  long k = 0;
  for (std::size_t i = 0; i < remove_flag_.size() && i < owned(); ++i)
    if (remove_flag_[i]) s[fmt::format("sim.pending_removal.{}", k++)] = double(id[i]);
}

template <int D>
void Simulation<D>::load_state(const std::map<std::string, double>& s) {
  // A checkpoint of an earlier version has no build state: the restart rebuilds at its
  // positions (bit-identical only if it was written right after a rebuild).
  if (auto c = s.find("sim.t_configuration"); c != s.end()) t_configuration_ = c->second;
  for (auto r = s.lower_bound("sim.removed."); r != s.end(); ++r) {
    if (r->first.rfind("sim.removed.", 0) != 0) break;
    const std::string key = r->first.substr(12);  // name.body
    const auto dot = key.rfind('.');
    std::size_t b = 0;
    const char* end = key.data() + key.size();
    if (dot == std::string::npos || std::from_chars(key.data() + dot + 1, end, b).ptr != end ||
        b >= removed_mass_.size())
      continue;  // not this version's key
    const std::string name = key.substr(0, dot);
    auto& v = name == "mass" ? removed_mass_ : removed_[name];
    v.resize(removed_mass_.size(), 0.0);
    v[b] = r->second;
  }
  auto it = s.find("sim.builds");
  restore_ = it != s.end();
  if (!restore_) return;
  builds_before_ = static_cast<int>(it->second);
  if (auto d = s.find("sim.dt0"); d != s.end()) dt0_ = d->second;
  pending_ids_.clear();
  for (auto r = s.lower_bound("sim.pending_removal."); r != s.end(); ++r) {
    if (r->first.rfind("sim.pending_removal.", 0) != 0) break;
    pending_ids_.push_back(static_cast<std::int64_t>(r->second));
  }
  rebuild_pending_ = s.count("sim.rebuild_requested") > 0;
}

template void Simulation<2>::init(bool);
template void Simulation<3>::init(bool);
template void Simulation<2>::keep_build_state();
template void Simulation<3>::keep_build_state();
template void Simulation<2>::restore_build_state();
template void Simulation<3>::restore_build_state();
template void Simulation<2>::flag_pending_removals();
template void Simulation<3>::flag_pending_removals();
template void Simulation<2>::account_removed(const std::vector<char>&);
template void Simulation<3>::account_removed(const std::vector<char>&);
template double Simulation<2>::removed(const std::string&, int) const;
template double Simulation<3>::removed(const std::string&, int) const;
template void Simulation<2>::save_state(std::map<std::string, double>&) const;
template void Simulation<3>::save_state(std::map<std::string, double>&) const;
template void Simulation<2>::load_state(const std::map<std::string, double>&);
template void Simulation<3>::load_state(const std::map<std::string, double>&);

}  // namespace monosph
