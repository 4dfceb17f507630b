#include "output/probes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <numeric>

#include "output/wall_pressure_probe.hpp"
#include "scene/expression.hpp"

namespace monosph {

std::vector<long> piece_sizes(const std::vector<double>& xyz, int dim, double link) {
  const std::size_t n = xyz.size() / dim;
  // Points sorted by their cell of side `link`; a point's links lie in the 3^dim cells around it.
  using Cell = std::array<long, 3>;
  std::vector<Cell> cell(n);
  for (std::size_t i = 0; i < n; ++i) {
    cell[i] = {0, 0, 0};
    for (int a = 0; a < dim; ++a)
      cell[i][a] = static_cast<long>(std::floor(xyz[i * dim + a] / link));
  }
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return cell[a] < cell[b]; });
  std::vector<Cell> sorted(n);
  for (std::size_t k = 0; k < n; ++k) sorted[k] = cell[order[k]];
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  const int reach = dim == 3 ? 1 : 0;
  for (std::size_t i = 0; i < n; ++i)
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -reach; dz <= reach; ++dz) {
          const Cell c = {cell[i][0] + dx, cell[i][1] + dy, cell[i][2] + dz};
          auto [lo, hi] = std::equal_range(sorted.begin(), sorted.end(), c);
          for (auto k = lo; k != hi; ++k) {
            const std::size_t j = order[k - sorted.begin()];
            if (j <= i) continue;
            double d2 = 0;
            for (int a = 0; a < dim; ++a) {
              const double d = xyz[i * dim + a] - xyz[j * dim + a];
              d2 += d * d;
            }
            if (d2 < link * link) parent[root(i)] = root(j);
          }
        }
  std::vector<long> count(n, 0);
  for (std::size_t i = 0; i < n; ++i) ++count[root(i)];
  std::vector<long> sizes;
  for (long c : count)
    if (c > 0) sizes.push_back(c);
  std::sort(sizes.rbegin(), sizes.rend());
  return sizes;
}

template <int D>
struct Probes<D>::Item {
  ProbeSpec spec;
  std::size_t index = 0;  // in the scene's list
  int field = -1, body = -1, bc = -1, target = -1;
  std::int64_t id = -1;  // tracked particle
  Expression weight;
  Module<D>* module = nullptr;                 // provides the values of a module's probe type
  std::unique_ptr<WallPressureProbe<D>> wall;  // wall_pressure: the sensor's points
};

template <int D>
Probes<D>::Probes(Simulation<D>& sim) {
  auto& p = sim.particles();
  const char* ax = "xyz";
  for (std::size_t k = 0; k < sim.scene().probes.size(); ++k) {
    const ProbeSpec& s = sim.scene().probes[k];
    auto it = std::make_unique<Item>();
    it->spec = s;
    it->index = k;
    const std::string where = "probes.list[" + std::to_string(k) + "]";
    if (!s.field.empty()) {
      it->field = p.find(s.field);
      if (it->field < 0) {
        std::string names;
        for (const auto& f : p.fields()) names += (names.empty() ? "" : ", ") + f.name;
        throw InputError(where + ".field: no particle field '" + s.field +
                         "' in this scene (available: " + names + ")");
      }
      const int nc = p.field(it->field).ncomp;
      if (nc > 1 && (s.component < 0 || s.component >= nc))
        throw InputError(where + ".field: '" + s.field + "' has " + std::to_string(nc) +
                         " components; name one, e.g. " + s.field + ".x");
    }
    for (const auto& m : sim.modules()) {  // a probe type of a physics module
      auto suffixes = m->probe_columns(s);
      if (suffixes.empty()) continue;
      it->module = m.get();
      for (const auto& c : suffixes) columns_.push_back(s.name + c);
      break;
    }
    if (it->module) {
      items_.push_back(std::move(it));
      continue;
    }
    if (s.type.rfind("rigid_", 0) == 0)
      throw InputError(where + ".type: '" + s.type + "' needs the clusters module (a rigid body)");
    if (s.type.rfind("solid_contact_", 0) == 0)
      throw InputError(where + ".type: '" + s.type + "' needs a solid_contact section");
    if (s.type.rfind("lubrication_", 0) == 0)
      throw InputError(where + ".type: '" + s.type + "' needs a lubrication section");
    if (s.type == "fluid_force")
      throw InputError(where + ".type: 'fluid_force' needs the fluid module (a fluid body)");
    if (s.type.rfind("surface_", 0) == 0)
      throw InputError(where + ".type: '" + s.type +
                       "' needs the rigid module (a surfaces section)");
    if (s.type == "reaction_force") {
      for (std::size_t b = 0; b < sim.boundaries().size(); ++b)
        if (sim.boundaries()[b].name == s.body) it->bc = static_cast<int>(b);
    } else if (!s.body.empty()) {
      for (std::size_t b = 0; b < sim.bodies().size(); ++b)
        if (sim.bodies()[b].name == s.body) it->body = static_cast<int>(b);
    }
    for (std::size_t b = 0; b < sim.bodies().size(); ++b)
      if (!s.target.empty() && sim.bodies()[b].name == s.target) it->target = static_cast<int>(b);
    if (s.type == "profile") {  // its own file, no column
      profiles_.push_back(std::make_unique<ProfileProbe<D>>(sim, s, it->field, it->body));
      continue;
    }
    if (s.type == "grain_impacts" || s.type == "contact_pairs")
      throw InputError(where + ".type: '" + s.type + "' needs the contact module (a rigid body)");
    if (s.type == "disorder" && !p.has("disorder"))
      throw InputError(where +
                       ".type: 'disorder' needs a solid body (the solid module computes it)");
    if (s.type == "wall_pressure")  // checks that the sensor sits on the body's face
      it->wall = std::make_unique<WallPressureProbe<D>>(sim, s, it->body, where);
    if (!s.weight_expr.empty())
      it->weight = Expression(s.weight_expr, where + ".weight", sim.scene().variables);
    if (s.type == "tracked") {  // the particle nearest to the point now, followed by its id
      double best = std::numeric_limits<double>::infinity();
      auto x = p.x();
      auto bd = p.body();
      for (std::size_t i = 0; i < sim.owned(); ++i) {
        if (it->body >= 0 && bd[i] != it->body) continue;
        double d2 = 0;
        for (int a = 0; a < D; ++a) d2 += (x[i][a] - s.point[a]) * (x[i][a] - s.point[a]);
        if (d2 < best) best = d2, it->id = p.id()[i];
      }
      double id = static_cast<double>(it->id);
      sim.comm().nearest(best, id);
      it->id = static_cast<std::int64_t>(id);
    }
    if (s.type == "momentum" || s.type == "reaction_force") {
      for (int a = 0; a < D; ++a) columns_.push_back(s.name + "_" + ax[a]);
    } else {
      columns_.push_back(s.name);
    }
    items_.push_back(std::move(it));
  }
}

template <int D>
Probes<D>::~Probes() = default;

template <int D>
void Probes<D>::open_profiles(const std::filesystem::path& dir, bool restarted, double time) {
  for (auto& pr : profiles_) pr->open(dir, restarted, time);
}

template <int D>
void Probes<D>::save_state(std::map<std::string, double>& s) const {
  for (const auto& it : items_)
    if (it->spec.type == "tracked")
      s["probes." + std::to_string(it->index) + ".tracked_id"] = static_cast<double>(it->id);
}

template <int D>
void Probes<D>::load_state(const std::map<std::string, double>& s) {
  for (auto& it : items_) {
    if (it->spec.type != "tracked") continue;
    const std::string key = "probes." + std::to_string(it->index) + ".tracked_id";
    auto f = s.find(key);
    if (f == s.end()) continue;  // an older checkpoint: the particle nearest to the point now
    const double id = f->second;
    if (!(id >= 0 && id < 9.0e15 && id == std::floor(id)))
      throw InputError("checkpoint: " + key + " is not a particle id");
    it->id = static_cast<std::int64_t>(id);
  }
}

template <int D>
const ProfileBins& Probes<D>::profile(const std::string& name) const {
  for (const auto& pr : profiles_)
    if (pr->name() == name) return pr->last();
  throw std::out_of_range("no profile probe named '" + name + "'");
}

namespace {

// The sample of one probe type over the owned particles i with in_body(i), reduced over the
// ranks (the probe types in README.md, "probes").
template <int D, class InBody>
double count_pieces(Simulation<D>& sim, InBody in_body, int min_particles) {
  auto x = sim.particles().x();
  const std::size_t n = sim.owned();
  const Comm& comm = sim.comm();
  // Connected pieces (particles closer than 1.5 dp linked) with at least min_particles
  // particles: a body broken into segments or fragments. Positions gather on rank 0.
  std::vector<double> local;
  for (std::size_t i = 0; i < n; ++i)
    if (in_body(i))
      for (int a = 0; a < D; ++a) local.push_back(x[i][a]);
  std::vector<std::vector<char>> send(comm.size());
  send[0].resize(local.size() * sizeof(double));
  if (!local.empty()) std::memcpy(send[0].data(), local.data(), send[0].size());
  std::vector<double> all;  // filled on rank 0 only
  for (const auto& buf : comm.exchange(send)) {
    const std::size_t m0 = all.size();
    all.resize(m0 + buf.size() / sizeof(double));
    if (!buf.empty()) std::memcpy(all.data() + m0, buf.data(), buf.size());
  }
  long count = 0;
  for (long c : piece_sizes(all, D, 1.5 * sim.dp())) count += c >= min_particles;
  return static_cast<double>(comm.sum(count));
}

template <int D, class InBody>
double penetration(Simulation<D>& sim, InBody in_body, int target) {
  auto& p = sim.particles();
  auto bd = p.body();
  const std::size_t n = sim.owned();
  const Comm& comm = sim.comm();
  // How far a particle of `body` comes closer than dp to a particle of `target` (every solid
  // particle without one): max(0, dp - r) over such pairs, in metres. Lattice neighbours at
  // rest are dp apart (0); a Hertz overlap or a fluid particle pushed into the solid shows.
  const auto& pl = sim.pairs();
  auto ph = p.phase();
  auto x = p.x();
  const double dp = sim.dp();
  double worst = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!in_body(i)) continue;
    for (std::size_t k = pl.begin(i); k < pl.end(i); ++k) {
      const int j = pl.j[k];
      if (target < 0 ? ph[j] != kSolid : bd[j] != target) continue;
      if (bd[j] == bd[i]) continue;
      worst = std::max(worst, dp - pl.r(x, i, k).norm());
    }
  }
  return comm.max(worst);
}

template <int D, class InBody>
double diameter(Simulation<D>& sim, InBody in_body, const ProbeSpec& s) {
  auto x = sim.particles().x();
  const std::size_t n = sim.owned();
  const Comm& comm = sim.comm();
  // 2 x the largest distance of a particle centre from the axis (through `point`, along
  // `axis`) + dp: the outer diameter of a round body whatever the lattice directions.
  double r2 = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!in_body(i)) continue;
    double d2 = 0, along = 0;
    for (int a = 0; a < D; ++a) along += (x[i][a] - s.point[a]) * s.axis[a];
    for (int a = 0; a < D; ++a) {
      const double c = x[i][a] - s.point[a] - along * s.axis[a];
      d2 += c * c;
    }
    r2 = std::max(r2, d2);
  }
  return 2 * std::sqrt(comm.max(r2)) + sim.dp();
}

template <int D, class InBody>
double rms_disorder(Simulation<D>& sim, InBody in_body) {
  auto& p = sim.particles();
  const std::size_t n = sim.owned();
  const Comm& comm = sim.comm();
  // RMS over the (solid) particles of the per-particle disorder, in dp
  auto dis = p.template view<double>("disorder");
  auto ph = p.phase();
  double sum = 0;
  std::size_t cnt = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (in_body(i) && ph[i] == kSolid) sum += dis[i] * dis[i], ++cnt;
  sum = comm.sum(sum);
  cnt = comm.sum(static_cast<long>(cnt));
  return cnt ? std::sqrt(sum / cnt) : 0.0;
}

template <int D, class InBody, class Value>
double value_at(Simulation<D>& sim, InBody in_body, Value value, const Point& point) {
  auto x = sim.particles().x();
  const std::size_t n = sim.owned();
  double best = std::numeric_limits<double>::infinity(), val = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!in_body(i)) continue;
    double d2 = 0;
    for (int a = 0; a < D; ++a) d2 += (x[i][a] - point[a]) * (x[i][a] - point[a]);
    if (d2 < best) best = d2, val = value(i);
  }
  sim.comm().nearest(best, val);
  return val;
}

}  // namespace

template <int D>
std::vector<double> Probes<D>::sample(Simulation<D>& sim) {
  auto& p = sim.particles();
  auto x = p.x();
  auto v = p.v();
  auto m = p.m();
  auto rho = p.rho();
  const std::size_t n = sim.owned();  // sums over owned particles, then over the ranks
  const Comm& comm = sim.comm();
  const int kdev = p.find("deviatoric_stress");
  std::span<Mat3> dev;
  if (kdev >= 0) dev = p.template view<Mat3>(kdev);
  auto bd = p.body();
  std::vector<double> out;
  for (auto& it : items_) {
    const auto& s = it->spec;
    if (it->module) {
      it->module->probe(sim, s, out);
      continue;
    }
    auto in_body = [&](std::size_t i) { return it->body < 0 || bd[i] == it->body; };
    auto value = [&](std::size_t i) {
      const Field& f = p.field(it->field);
      const int c = f.ncomp > 1 ? s.component : 0;
      return f.type == FieldType::Real ? f.real[i * f.ncomp + c]
                                       : static_cast<double>(f.ints[i * f.ncomp + c]);
    };
    // Elastic energy V (S:S / (4 mu) + p^2 / (2 K)) of a solid particle (0 for the others).
    auto elastic = [&, ph = p.phase(), mt = p.material(), pr = p.p()](std::size_t i) {
      if (ph[i] != kSolid) return 0.0;
      const Material& mm = sim.materials()[mt[i]];
      double ss = 0;
      if (kdev >= 0 && mm.shear_modulus > 0) {
        const Mat3& S = dev[i];
        ss = S.cwiseProduct(S).sum() / (4 * mm.shear_modulus);
      }
      return m[i] / rho[i] * (ss + pr[i] * pr[i] / (2 * mm.bulk_modulus));
    };
    // This rank's share of the energy stored in contacts (grain contact, rigid surfaces).
    auto contact_energy = [&] {
      double e = 0;
      for (const auto& mod : sim.modules()) e += mod->potential_energy(sim);
      return e;
    };
    auto weight = [&](std::size_t i) {
      if (it->weight.empty()) return 1.0;
      return it->weight(x[i][0], x[i][1], D == 3 ? x[i][D - 1] : 0.0, sim.time());
    };
    if (s.type == "total_energy") {
      // kinetic + elastic and hourglass-spring energy (solids) + potential of each body's constant
      // body force, -m g.x; + the energy of the contacts when it is the whole scene's; + the
      // elastic energy failed particles released (failure_energy); + what eroded particles took
      const int kh = p.find("hourglass_energy");
      const int kf = p.find("failure_energy");
      double e = it->body < 0 ? contact_energy() : 0.0;
      // Eroded particles: their kinetic, released and spring energy (summed over the ranks).
      double gone = 0;
      for (const char* q : {"kinetic_energy", "failure_energy", "hourglass_energy"})
        gone += sim.removed(q, it->body);
      for (std::size_t i = 0; i < n; ++i) {
        if (!in_body(i)) continue;
        e += 0.5 * m[i] * v[i].squaredNorm() - m[i] * sim.body_force(bd[i]).dot(x[i]) + elastic(i);
        if (kh >= 0) e += p.template view<double>(kh)[i];  // hourglass springs (solid module)
        if (kf >= 0) e += p.template view<double>(kf)[i];  // released at failure (solid module)
      }
      out.push_back(comm.sum(e) + gone);
    } else if (s.type == "failure_energy" || s.type == "plastic_work") {
      // Per-particle energies of the solid module, eroded particles' included.
      const int kf = p.find(s.type);
      double e = 0;
      for (std::size_t i = 0; i < n && kf >= 0; ++i)
        if (in_body(i)) e += p.template view<double>(kf)[i];
      out.push_back(comm.sum(e) + sim.removed(s.type, it->body));
    } else if (s.type == "kinetic_share") {
      // Kinetic energy over plastic work (eroded particles' included), e.g. to check that mass
      // scaling keeps a cut quasi-static; 0 before any plastic work.
      const int kw = p.find("plastic_work");
      double e = 0, w = 0;
      for (std::size_t i = 0; i < n; ++i) {
        if (!in_body(i)) continue;
        e += 0.5 * m[i] * v[i].squaredNorm();
        if (kw >= 0) w += p.template view<double>(kw)[i];
      }
      w = comm.sum(w) + sim.removed("plastic_work", it->body);
      e = comm.sum(e);
      out.push_back(w > 0 ? e / w : 0.0);
    } else if (s.type == "contact_energy") {
      out.push_back(comm.sum(contact_energy()));
    } else if (s.type == "kinetic_energy") {
      double e = 0;
      for (std::size_t i = 0; i < n; ++i)
        if (in_body(i)) e += 0.5 * m[i] * v[i].squaredNorm() * weight(i);
      out.push_back(comm.sum(e));
    } else if (s.type == "elastic_energy") {
      double e = 0;
      for (std::size_t i = 0; i < n; ++i)
        if (in_body(i)) e += elastic(i);
      out.push_back(comm.sum(e));
    } else if (s.type == "disorder") {
      out.push_back(rms_disorder(sim, in_body));
    } else if (s.type == "total_mass") {
      double e = 0;
      for (std::size_t i = 0; i < n; ++i)
        if (in_body(i)) e += m[i];
      out.push_back(comm.sum(e));
    } else if (s.type == "momentum") {
      Vec<D> q = Vec<D>::Zero();
      for (std::size_t i = 0; i < n; ++i)
        if (in_body(i)) q += m[i] * v[i];
      comm.sum(std::span<double>(q.data(), D));
      for (int a = 0; a < D; ++a) out.push_back(q[a]);
    } else if (s.type == "abs_momentum") {
      double e = 0;
      for (std::size_t i = 0; i < n; ++i)
        if (in_body(i)) e += m[i] * v[i].norm();
      out.push_back(comm.sum(e));
    } else if (s.type == "max_speed") {
      double e = 0;
      for (std::size_t i = 0; i < n; ++i)
        if (in_body(i)) e = std::max(e, v[i].norm());
      out.push_back(comm.max(e));
    } else if (s.type == "min_distance") {
      out.push_back(comm.min(sim.min_distance()) / sim.dp());
    } else if (s.type == "diameter") {
      out.push_back(diameter(sim, in_body, s));
    } else if (s.type == "extent") {  // max - min of a component; + dp for position (outer faces)
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for (std::size_t i = 0; i < n; ++i)
        if (in_body(i)) lo = std::min(lo, value(i)), hi = std::max(hi, value(i));
      lo = comm.min(lo), hi = comm.max(hi);
      out.push_back(hi - lo + (s.field == "position" ? sim.dp() : 0.0));
    } else if (s.type == "field_max" || s.type == "field_min") {  // extreme of a field component
      const bool mx = s.type == "field_max";
      double e =
          mx ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i < n; ++i)
        if (in_body(i)) e = mx ? std::max(e, value(i)) : std::min(e, value(i));
      out.push_back(mx ? comm.max(e) : comm.min(e));
    } else if (s.type == "integral" || s.type == "mean") {
      double sum = 0, vol = 0;
      for (std::size_t i = 0; i < n; ++i) {
        if (!in_body(i)) continue;
        const double vi = m[i] / rho[i];
        sum += vi * value(i) * weight(i);
        vol += vi;
      }
      sum = comm.sum(sum), vol = comm.sum(vol);
      out.push_back(s.type == "mean" ? sum / vol : sum);
    } else if (s.type == "value_at") {  // the value of the particle nearest to `point`
      out.push_back(value_at(sim, in_body, value, s.point));
    } else if (s.type == "tracked") {
      auto ids = p.id();
      double val = 0, found = 0;
      for (std::size_t i = 0; i < n; ++i)
        if (ids[i] == it->id) val = value(i), found = 1;
      val = comm.sum(val), found = comm.sum(found);  // one owner
      out.push_back(found > 0 ? val : std::numeric_limits<double>::quiet_NaN());
    } else if (s.type == "pieces") {
      out.push_back(count_pieces(sim, in_body, s.min_particles));
    } else if (s.type == "wall_pressure") {  // mean interpolated pressure over the sensor
      out.push_back(it->wall->sample(sim));
    } else if (s.type == "removed_mass") {  // eroded particles (all bodies, or `body`)
      out.push_back(sim.removed("mass", it->body));
    } else if (s.type == "reaction_force") {
      for (int a = 0; a < D; ++a) out.push_back(sim.reactions()[it->bc][a]);
    } else if (s.type == "penetration") {
      out.push_back(penetration(sim, in_body, it->target));
    }
  }
  for (auto& pr : profiles_) pr->sample(sim);
  return out;
}

double measure_series(const std::string& measure, const std::vector<double>& t,
                      const std::vector<double>& y, double start, std::string* why) {
  std::vector<double> tt, yy;
  for (std::size_t k = 0; k < t.size(); ++k)
    if (t[k] >= start) tt.push_back(t[k]), yy.push_back(y[k]);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto none = [&](const std::string& reason) {
    if (why) *why = reason;
    return nan;
  };
  if (tt.empty()) return none(fmt::format("no probe sample at or after t = {:g} s", start));
  if (measure == "final") return yy.back();
  if (measure == "max") return *std::max_element(yy.begin(), yy.end());
  if (measure == "min") return *std::min_element(yy.begin(), yy.end());
  const double mean = std::accumulate(yy.begin(), yy.end(), 0.0) / yy.size();
  if (measure == "mean") return mean;
  if (measure == "harmonic_mean") {  // n / sum(1/y): the ratio of means of a reciprocal rate
    double inv = 0;
    for (double y : yy) {
      if (!(y > 0)) return none(fmt::format("a probe sample is not positive ({:g})", y));
      inv += 1 / y;
    }
    return static_cast<double>(yy.size()) / inv;
  }
  if (measure == "std") {  // sample standard deviation over the window
    if (yy.size() < 2) return none("fewer than two probe samples");
    double ss = 0;
    for (double y : yy) ss += (y - mean) * (y - mean);
    return std::sqrt(ss / static_cast<double>(yy.size() - 1));
  }
  if (measure == "drift") {  // largest relative change from the first sample
    double d = 0;
    for (double y : yy) d = std::max(d, std::abs(y - yy[0]));
    return yy[0] != 0 ? d / std::abs(yy[0]) : d;
  }
  if (measure == "trend") {
    // Secular drift of an oscillating quantity (e.g. an energy that swaps between parts measured
    // with different discretisation errors): the change between its means over the first and the
    // last whole oscillation cycle, relative to the first. Cycles run between upward crossings of
    // the residual from a least-squares line; without two cycles, the line's change is used.
    const double n = static_cast<double>(tt.size());
    if (tt.size() < 2) return none("fewer than two probe samples");
    const double tm = std::accumulate(tt.begin(), tt.end(), 0.0) / n;
    double stt = 0, sty = 0;
    for (std::size_t k = 0; k < tt.size(); ++k)
      stt += (tt[k] - tm) * (tt[k] - tm), sty += (tt[k] - tm) * (yy[k] - mean);
    if (!(stt > 0)) return none("all probe samples at one time");
    const double b = sty / stt;
    auto res = [&](std::size_t k) { return yy[k] - mean - b * (tt[k] - tm); };
    double rms = 0;
    for (std::size_t k = 0; k < tt.size(); ++k) rms += res(k) * res(k);
    rms = std::sqrt(rms / n);
    // First sample after each upward crossing; the residual must have been below -rms/4 since the
    // last one (round-off or small ripples are no cycles).
    std::vector<std::size_t> up;
    bool armed = false;
    for (std::size_t k = 0; k < tt.size() && rms > 1e-12 * std::abs(mean); ++k) {
      if (res(k) < -0.25 * rms) armed = true;
      if (armed && res(k) >= 0) up.push_back(k), armed = false;
    }
    auto cycle_mean = [&](std::size_t k0, std::size_t k1) {  // trapezoid mean over [t_k0, t_k1]
      double sum = 0;
      for (std::size_t k = k0; k < k1; ++k) sum += 0.5 * (yy[k] + yy[k + 1]) * (tt[k + 1] - tt[k]);
      return sum / (tt[k1] - tt[k0]);
    };
    if (up.size() >= 3) {
      const double first = cycle_mean(up[0], up[1]);
      const double last = cycle_mean(up[up.size() - 2], up.back());
      return first != 0 ? (last - first) / std::abs(first) : last - first;
    }
    const double y0 = mean + b * (tt.front() - tm), change = b * (tt.back() - tt.front());
    return y0 != 0 ? change / std::abs(y0) : change;
  }
  if (measure == "growth") {  // largest relative increase over the first sample (0 if none)
    double d = 0;
    for (double y : yy) d = std::max(d, y - yy[0]);
    return yy[0] != 0 ? d / std::abs(yy[0]) : d;
  }
  if (measure == "peak_ratio") {
    // last local maximum of y - y(start) over the first one: amplitude retention
    std::vector<double> peaks;
    for (std::size_t k = 1; k + 1 < yy.size(); ++k)
      if (yy[k] > yy[k - 1] && yy[k] >= yy[k + 1] && yy[k] > yy[0]) peaks.push_back(yy[k] - yy[0]);
    if (peaks.size() < 2)
      return none(
          fmt::format("fewer than two peaks above the first sample (found {})", peaks.size()));
    return peaks.back() / peaks.front();
  }
  // frequency / period from the upward zero crossings of y - mean (linear interpolation);
  // same-direction crossings make the estimate insensitive to an offset in the mean.
  std::vector<double> cross;
  for (std::size_t k = 1; k < yy.size(); ++k) {
    const double a = yy[k - 1] - mean, b = yy[k] - mean;
    if (a < 0 && b >= 0) cross.push_back(tt[k - 1] + (tt[k] - tt[k - 1]) * a / (a - b));
  }
  if (cross.size() < 2)
    return none(
        fmt::format("fewer than two upward crossings of the mean (found {}): the run "
                    "is shorter than one period, or the probe does not oscillate",
                    cross.size()));
  const double f = (cross.size() - 1) / (cross.back() - cross.front());
  if (measure == "frequency") return f;
  if (measure == "angular_frequency") return 2 * std::numbers::pi * f;
  if (measure == "period") return 1.0 / f;
  return none("unknown measure '" + measure + "'");
}

template class Probes<2>;
template class Probes<3>;

}  // namespace monosph
