#include "core/mirror.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace monosph {

bool mirror_point_field(const std::string& name) {
  // The current position and the reference positions of the solid module (initial and
  // intermediate reference configuration, MMB Eq. 28-30).
  return name == "position" || name == "initial_position" || name == "reference_position";
}

template <int D>
Mirror<D>::Mirror(const Domain<D>& dom, std::vector<bool> lo, std::vector<bool> hi, double halo)
    : halo_(halo) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  lo_.assign(D, nan), hi_.assign(D, nan);
  for (int a = 0; a < D; ++a) {
    if (lo[a]) lo_[a] = dom.lo[a];
    if (hi[a]) hi_[a] = dom.hi[a];
  }
}

template <int D>
Domain<D> Mirror<D>::extended(const Domain<D>& dom) const {
  Domain<D> e = dom;
  for (int a = 0; a < D; ++a) {
    if (!std::isnan(lo_[a])) e.lo[a] -= halo_;
    if (!std::isnan(hi_[a])) e.hi[a] += halo_;
  }
  return e;
}

template <int D>
void Mirror<D>::make_ghosts(Particles<D>& p) {
  put_back(p);
  owned_ = p.size();
  src_.clear(), sign_.clear(), offset_.clear();
  auto x = p.x();
  for (std::size_t i = 0; i < owned_; ++i) {
    // Per axis: 0 no plane near, else the coordinate of the near plane (at most one per axis:
    // with both faces of an axis within the halo, each gets its own single-plane image).
    std::array<int, D> near{};  // bit 0: lo plane near, bit 1: hi plane near
    bool any = false;
    for (int a = 0; a < D; ++a) {
      if (!std::isnan(lo_[a]) && x[i][a] - lo_[a] < halo_) near[a] |= 1;
      if (!std::isnan(hi_[a]) && hi_[a] - x[i][a] < halo_) near[a] |= 2;
      any = any || near[a];
    }
    if (!any) continue;
    // Every combination of one choice per axis (none, lo, hi where near) but "none" everywhere.
    std::array<int, D> c{};
    while (true) {
      int a = 0;
      while (a < D) {
        do ++c[a];
        while (c[a] < 3 && !(near[a] & c[a]));
        if (c[a] < 3) break;
        c[a] = 0, ++a;
      }
      if (a == D) break;
      Vec<D> s = Vec<D>::Ones(), off = Vec<D>::Zero();
      for (int b = 0; b < D; ++b)
        if (c[b]) s[b] = -1, off[b] = 2 * (c[b] == 1 ? lo_[b] : hi_[b]);
      src_.push_back(static_cast<int>(i)), sign_.push_back(s), offset_.push_back(off);
    }
  }
  p.resize(owned_ + src_.size());
  std::vector<int> all(p.fields().size());
  for (std::size_t k = 0; k < all.size(); ++k) all[k] = static_cast<int>(k);
  exchange(p, all);
}

namespace {
// Reflection of one particle's value of a field with c components: in -> out (may alias).
template <int D>
void reflect_value(const double* in, double* out, std::size_t c, bool point, const Vec<D>& s,
                   const Vec<D>& off) {
  // Tensors: D x D, or 3 x 3 in 2D (the z row and column are not reflected).
  const int t = c == D * D ? D : (D == 2 && c == 9) ? 3 : 0;
  if (c == 1) {
    out[0] = in[0];
  } else if (c == D && point) {
    for (int a = 0; a < D; ++a) out[a] = off[a] + s[a] * in[a];
  } else if (c == D && !t) {
    for (int a = 0; a < D; ++a) out[a] = s[a] * in[a];
  } else {  // R T R: entry (a, b) times s_a s_b (the sign pattern is symmetric: any storage order)
    for (int a = 0; a < t; ++a)
      for (int b = 0; b < t; ++b)
        out[a * t + b] = (a < D ? s[a] : 1.0) * (b < D ? s[b] : 1.0) * in[a * t + b];
  }
}

void check_rule(int dim, const Field& f) {
  const int c = f.ncomp;
  if (f.type == FieldType::Real && c != 1 && c != dim && c != dim * dim && !(dim == 2 && c == 9))
    throw std::logic_error("domain.mirror: no reflection rule for the field '" + f.name + "' (" +
                           std::to_string(c) + " components)");
}
}  // namespace

template <int D>
void Mirror<D>::reflect(Field& f, const std::string& name) const {
  check_rule(D, f);
  const std::size_t n = src_.size(), c = static_cast<std::size_t>(f.ncomp);
  if (f.type == FieldType::Int) {
    for (std::size_t g = 0; g < n; ++g)
      for (std::size_t q = 0; q < c; ++q) f.ints[(owned_ + g) * c + q] = f.ints[src_[g] * c + q];
    return;
  }
  double* v = f.real.data();
  const bool point = mirror_point_field(name);
  for (std::size_t g = 0; g < n; ++g)
    reflect_value<D>(v + src_[g] * c, v + (owned_ + g) * c, c, point, sign_[g], offset_[g]);
}

template <int D>
void Mirror<D>::put_back(Particles<D>& p) const {
  // A particle beyond a plane is replaced by its image (all fields reflected): the image of a
  // crossing particle is the particle of the other half that has entered this one.
  auto x = p.x();
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int a = 0; a < D; ++a) {
      const bool below = !std::isnan(lo_[a]) && x[i][a] < lo_[a];
      const bool above = !std::isnan(hi_[a]) && x[i][a] > hi_[a];
      if (!below && !above) continue;
      Vec<D> s = Vec<D>::Ones(), off = Vec<D>::Zero();
      s[a] = -1, off[a] = 2 * (below ? lo_[a] : hi_[a]);
      for (auto& f : p.fields())
        if (f.type == FieldType::Real) {
          check_rule(D, f);
          const std::size_t c = static_cast<std::size_t>(f.ncomp);
          reflect_value<D>(&f.real[i * c], &f.real[i * c], c, mirror_point_field(f.name), s, off);
        }
    }
}

template <int D>
void Mirror<D>::exchange(Particles<D>& p, std::span<const int> fields) const {
  if (src_.empty()) return;
  for (int k : fields)
    if (k >= 0) reflect(p.field(k), p.field(k).name);
}

template class Mirror<2>;
template class Mirror<3>;

}  // namespace monosph
