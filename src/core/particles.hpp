#pragma once
// Particles<D>: one structure-of-arrays container for every phase. Always-present fields plus
// fields that modules register on demand; removal with compaction; permutation for locality.
#include <initializer_list>
#include <span>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace monosph {

enum class FieldType { Real, Int };

struct Field {
  std::string name;
  int ncomp = 1;  // components per particle
  FieldType type = FieldType::Real;
  std::vector<double> real;
  std::vector<std::int64_t> ints;
  bool output = false;  // written to VTK frames
  // Phases (bit 1 << phase) where the field has a meaning; a frame shows NaN ("no value") for
  // the other particles, so e.g. a wall does not show a temperature. Set by the owning module.
  unsigned phases = ~0u;
  // 2D DxD tensors are written as 3x3; the zz entry is this (1 for a deformation gradient, so
  // that ParaView's determinant and eigenvalues are right), the other new entries 0.
  double pad_zz = 0;
  std::size_t size() const { return type == FieldType::Real ? real.size() : ints.size(); }
};

template <int D>
class Particles {
 public:
  using V = Vec<D>;
  using M = Mat<D>;

  Particles();

  std::size_t size() const { return n_; }
  // Adds n particles (fields zero-initialised, ids fresh); returns the first new index.
  std::size_t append(std::size_t n);
  void resize(std::size_t n);
  // new[i] = old[order[i]] for every field.
  void permute(const std::vector<int>& order);
  // Keeps the particles keep[0] < keep[1] < ... in that order, in place.
  void compact(const std::vector<int>& keep);
  // Removes flagged particles, keeping the order of the others. Returns how many were removed.
  std::size_t remove(const std::vector<char>& flag);

  // Registers a field (idempotent if the shape matches); returns its index.
  int add_field(const std::string& name, int ncomp, FieldType type = FieldType::Real,
                bool output = false);
  // Sets Field::phases (and pad_zz) of the fields ks; indices < 0 (fields not registered) skip.
  void set_meaning(std::initializer_list<int> ks, unsigned phases, double pad_zz = 0);
  bool has(const std::string& name) const { return find(name) >= 0; }
  int find(const std::string& name) const;
  Field& field(int k) { return fields_[k]; }
  const Field& field(int k) const { return fields_[k]; }
  Field& field(const std::string& name);
  const Field& field(const std::string& name) const;
  std::vector<Field>& fields() { return fields_; }
  const std::vector<Field>& fields() const { return fields_; }

  // Typed views of a field: T = double, Vec<D>, Mat<D>, Mat3, std::int64_t.
  template <class T>
  std::span<T> view(int k) {
    Field& f = fields_[k];
    if constexpr (std::is_same_v<T, std::int64_t>) {
      return {f.ints.data(), n_};
    } else {
      static_assert(sizeof(T) % sizeof(double) == 0);
      return {reinterpret_cast<T*>(f.real.data()), n_};
    }
  }
  template <class T>
  std::span<T> view(const std::string& name) {
    int k = find(name);
    if (k < 0) throw std::logic_error("no particle field '" + name + "'");
    return view<T>(k);
  }

  // Always-present fields.
  std::span<V> x() { return view<V>(kx_); }
  std::span<V> v() { return view<V>(kv_); }
  std::span<V> a() { return view<V>(ka_); }
  std::span<double> m() { return view<double>(km_); }
  std::span<double> rho() { return view<double>(krho_); }
  std::span<double> drho() { return view<double>(kdrho_); }
  std::span<double> p() { return view<double>(kp_); }
  std::span<std::int64_t> phase() { return view<std::int64_t>(kphase_); }
  std::span<std::int64_t> material() { return view<std::int64_t>(kmat_); }
  std::span<std::int64_t> body() { return view<std::int64_t>(kbody_); }
  std::span<std::int64_t> id() { return view<std::int64_t>(kid_); }

  std::int64_t next_id() const { return next_id_; }
  void set_next_id(std::int64_t v) { next_id_ = v; }

 private:
  std::size_t n_ = 0;
  std::int64_t next_id_ = 0;
  std::vector<Field> fields_;
  int kx_, kv_, ka_, km_, krho_, kdrho_, kp_, kphase_, kmat_, kbody_, kid_;
};

}  // namespace monosph
