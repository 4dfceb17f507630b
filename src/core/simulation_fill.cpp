// Filling the bodies on the lattice at a fresh start (Simulation::create_particles).
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <sstream>
#include <unordered_map>

#include "core/shell_fill.hpp"
#include "core/simulation.hpp"

namespace monosph {

template <int D>
void Simulation<D>::create_particles() {
  // A rank stops with the others when its share of the scene is bad (MPI).
  std::string err;
  try {
    fill_bodies();
  } catch (const InputError& e) {
    err = e.what();
  }
  err = comm_.first_message(err);
  if (!err.empty()) throw InputError(err);
  // Boundary-condition membership.
  if (kbc_ >= 0) {
    auto bc = p_.template view<std::int64_t>(kbc_);
    auto x = p_.x();
    auto bd = p_.body();
    for (std::size_t k = 0; k < scene_.boundaries.size(); ++k) {
      const auto& s = scene_.boundaries[k];
      long count = 0;
      for (std::size_t i = 0; i < p_.size(); ++i) {
        bool in;
        if (s.point) {
          in = false;  // chosen below
        } else if (s.region) {
          Point xi(x[i].data(), x[i].data() + D);
          in = s.region->contains(xi);
        } else {
          in = scene_.bodies[bd[i]].name == s.body;
        }
        if (in) bc[i] = static_cast<std::int64_t>(k + 1), ++count;
      }
      if (s.point) {  // the particle nearest to the point (the lowest rank's on a tie)
        double best = std::numeric_limits<double>::infinity(), id = -1;
        for (std::size_t i = 0; i < p_.size(); ++i) {
          double d2 = 0;
          for (int a = 0; a < D; ++a) d2 += (x[i][a] - (*s.point)[a]) * (x[i][a] - (*s.point)[a]);
          if (d2 < best) best = d2, id = static_cast<double>(p_.id()[i]);
        }
        comm_.nearest(best, id);
        for (std::size_t i = 0; i < p_.size(); ++i)
          if (static_cast<double>(p_.id()[i]) == id)
            bc[i] = static_cast<std::int64_t>(k + 1), ++count;
      }
      if (comm_.sum(count) == 0)
        throw InputError("boundary_conditions[" + std::to_string(k) + "]: selects no particle");
    }
  }
  if (dec_) dec_->adopt(p_);  // every rank holds its own slab: the first rebuild balances
  if (mirror_) mirror_->adopt(p_);
  for (auto& m : modules_) m->on_create(*this);
}

namespace {

// Jitter draws dim numbers in [-1, 1] per accepted node in lattice order, kept or not (so that
// a rank's nodes get the serial run's numbers); returns those of the nodes `ids` (ascending).
std::vector<double> jitter_draws(unsigned seed, int dim, std::int64_t accepted,
                                 const std::vector<std::int64_t>& ids) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  std::vector<double> jit;
  jit.reserve(ids.size() * dim);
  std::size_t q = 0;
  for (std::int64_t n = 0; n < accepted; ++n) {
    const bool keep = q < ids.size() && ids[q] == n;
    for (int a = 0; a < dim; ++a) {
      const double u = uni(rng);
      if (keep) jit.push_back(u);
    }
    if (keep) ++q;
  }
  return jit;
}

// `rotate`: particle x turned about the body's point (after the fill, before anything reads it);
// it must stay in the domain.
template <int D>
void turn(Vec<D>& x, const BodySpec& body, std::size_t b, const Scene& scene) {
  const Point r = body.rotate->apply(Point(x.data(), x.data() + D));
  for (int a = 0; a < D; ++a)
    if (!(r[a] >= scene.domain_min[a] && r[a] <= scene.domain_max[a])) {
      std::ostringstream os;
      os << "bodies[" << b << "] (" << body.name
         << ").rotate: turns a particle out of the domain, to (";
      for (int c = 0; c < D; ++c) os << (c ? ", " : "") << r[c];
      throw InputError(os.str() + ")");
    }
  for (int a = 0; a < D; ++a) x[a] = r[a];
}

}  // namespace

template <int D>
void Simulation<D>::fill_bodies() {
  const double dp = scene_.dp;
  // Global lattice: nodes at domain.min + (k + 1/2) dp. Later bodies may not overlap earlier ones.
  // Bodies with `fill: rest` come last and take only the nodes no other body took; bodies with
  // `fill: shells` take body-fitted points (shell_fill.hpp) instead of lattice nodes.
  // MPI: every rank walks every node (so ids and jitter are the serial run's) but keeps only the
  // nodes of its slab along the longest axis, so no rank ever holds the whole scene.
  std::array<long, D> nk;
  int slab_axis = 0;
  for (int a = 0; a < D; ++a) {
    nk[a] = static_cast<long>(std::floor((scene_.domain_max[a] - scene_.domain_min[a]) / dp + 0.5));
    if (nk[a] > nk[slab_axis]) slab_axis = a;
  }
  const long r = comm_.rank(), nr = comm_.size();
  const long slab0 = nk[slab_axis] * r / nr, slab1 = nk[slab_axis] * (r + 1) / nr;
  std::unordered_map<std::int64_t, int> node_owner;  // nodes of this rank's slab
  std::vector<std::size_t> order;
  for (int pass = 0; pass < 2; ++pass)
    for (std::size_t b = 0; b < scene_.bodies.size(); ++b)
      if (scene_.bodies[b].fill_rest == (pass == 1)) order.push_back(b);
  std::vector<std::size_t> done;          // bodies filled so far
  std::vector<std::size_t> shell_bodies;  // of them, those with `fill: shells`
  std::int64_t next_id = 0;
  for (std::size_t b : order) {
    const BodySpec& body = scene_.bodies[b];
    Point lo, hi;
    body.shape.bounds(lo, hi);
    std::array<long, D> k0, k1;
    for (int a = 0; a < D; ++a) {
      k0[a] =
          std::max(0L, static_cast<long>(std::floor((lo[a] - scene_.domain_min[a]) / dp - 0.5)));
      k1[a] =
          std::min(nk[a] - 1, static_cast<long>(std::ceil((hi[a] - scene_.domain_min[a]) / dp)));
    }
    // A node another (earlier) body holds: known from its shape on every rank, its slab or not.
    auto taken = [&](const Point& x) {
      for (std::size_t o : done)
        if (scene_.bodies[o].shape.contains(x)) return true;
      return false;
    };
    std::vector<Point> pts;
    std::vector<std::int64_t> ids;
    std::vector<double> vols;  // `fill: shells`: each point's volume (else dp^D)
    std::int64_t accepted = 0;
    auto overlap = [&](const Point& x, std::size_t other) {
      std::ostringstream os;
      os << "bodies[" << b << "] (" << body.name << ").shape: overlaps body '"
         << scene_.bodies[other].name << "' at (";
      for (int a = 0; a < D; ++a) os << (a ? ", " : "") << x[a];
      os << ")";
      throw InputError(os.str());
    };
    if (body.fill_shells) {
      for (const ShellPoint& q : shell_points(body.shape, D, dp)) {
        for (std::size_t o : done)
          if (scene_.bodies[o].shape.contains(q.x)) overlap(q.x, o);
        const long ks = std::clamp(
            static_cast<long>(std::floor((q.x[slab_axis] - scene_.domain_min[slab_axis]) / dp)), 0L,
            nk[slab_axis] - 1);
        if (ks >= slab0 && ks < slab1)
          pts.push_back(q.x), ids.push_back(accepted), vols.push_back(q.volume);
        ++accepted;
      }
      shell_bodies.push_back(b);
    }
    std::array<long, D> k = k0;
    while (!body.fill_shells) {
      Point x(D);
      std::int64_t key = 0, mul = 1;
      for (int a = 0; a < D; ++a) {
        x[a] = scene_.domain_min[a] + (k[a] + 0.5) * dp;
        key += k[a] * mul;
        mul *= nk[a] + 1;
      }
      const bool mine = k[slab_axis] >= slab0 && k[slab_axis] < slab1;
      if (body.shape.contains(x)) {
        if (body.fill_rest) {
          if (!taken(x)) {
            if (mine) pts.push_back(x), ids.push_back(accepted);
            ++accepted;
          }
        } else {
          for (std::size_t o : shell_bodies)
            if (scene_.bodies[o].shape.contains(x)) overlap(x, o);
          if (mine) {
            auto [it, fresh] = node_owner.emplace(key, static_cast<int>(b));
            if (!fresh) overlap(x, static_cast<std::size_t>(it->second));
            pts.push_back(x), ids.push_back(accepted);
          }
          ++accepted;
        }
      }
      int a = 0;
      while (a < D && ++k[a] > k1[a]) k[a] = k0[a], ++a;
      if (a == D) break;
    }
    done.push_back(b);
    if (accepted == 0)
      throw InputError("bodies[" + std::to_string(b) + "] (" + body.name +
                       ").shape: contains no lattice node at dp = " + fmt::format("{:g}", dp));
    const std::vector<double> jit =
        body.jitter != 0 ? jitter_draws(body.seed, D, accepted, ids) : std::vector<double>{};
    const Material& mat = scene_.materials[body.material];
    Expression rho_ex, vel_ex[3];
    if (!body.density_expr.empty())
      rho_ex = Expression(body.density_expr, body.name + ".initial.density", scene_.variables);
    for (std::size_t a = 0; a < body.velocity_expr.size(); ++a)
      vel_ex[a] =
          Expression(body.velocity_expr[a], body.name + ".initial.velocity", scene_.variables);
    std::size_t first = p_.append(pts.size());
    auto x = p_.x();
    auto v = p_.v();
    auto m = p_.m();
    auto rho = p_.rho();
    auto ph = p_.phase();
    auto mt = p_.material();
    auto bd = p_.body();
    auto pid = p_.id();
    const double vol = std::pow(dp, D);  // per unit depth in 2D
    const std::string at = "bodies[" + std::to_string(b) + "] (" + body.name + ").initial.";
    for (std::size_t q = 0; q < pts.size(); ++q) {
      const std::size_t i = first + q;
      pid[i] = next_id + ids[q];
      for (int a = 0; a < D; ++a)
        x[i][a] = pts[q][a] + (jit.empty() ? 0.0 : body.jitter * dp * jit[q * D + a]);
      if (body.rotate) turn<D>(x[i], body, b, scene_);
      const double xx = x[i][0], yy = x[i][1], zz = D == 3 ? x[i][D - 1] : 0.0;
      rho[i] = rho_ex.empty() ? mat.density : rho_ex(xx, yy, zz, 0.0);
      if (!(rho[i] > 0) || !std::isfinite(rho[i]))  // inf passes > 0
        throw InputError(at + "density: not a positive finite value at a particle (" +
                         std::to_string(rho[i]) + ")");
      m[i] = rho[i] * (vols.empty() ? vol : vols[q]);
      for (int a = 0; a < D; ++a) {
        v[i][a] = body.velocity_expr.empty() ? 0.0 : vel_ex[a](xx, yy, zz, 0.0);
        if (!std::isfinite(v[i][a]))
          throw InputError(at + "velocity[" + std::to_string(a) + "]: not finite at a particle");
      }
      ph[i] = bodies_[b].phase;
      mt[i] = body.material;
      bd[i] = static_cast<std::int64_t>(b);
    }
    next_id += accepted;
  }
  p_.set_next_id(next_id);
}

template void Simulation<2>::create_particles();
template void Simulation<3>::create_particles();
template void Simulation<2>::fill_bodies();
template void Simulation<3>::fill_bodies();

}  // namespace monosph
