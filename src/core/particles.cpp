#include "core/particles.hpp"

#include <algorithm>
#include <numeric>

namespace monosph {

template <int D>
Particles<D>::Particles() {
  kx_ = add_field("position", D, FieldType::Real, false);
  kv_ = add_field("velocity", D, FieldType::Real, true);
  ka_ = add_field("acceleration", D, FieldType::Real, false);
  km_ = add_field("mass", 1, FieldType::Real, false);
  krho_ = add_field("density", 1, FieldType::Real, true);
  kdrho_ = add_field("density_rate", 1, FieldType::Real, false);
  kp_ = add_field("pressure", 1, FieldType::Real, true);
  kphase_ = add_field("phase", 1, FieldType::Int, true);
  kmat_ = add_field("material", 1, FieldType::Int, false);
  kbody_ = add_field("body", 1, FieldType::Int, true);
  kid_ = add_field("id", 1, FieldType::Int, true);
}

template <int D>
int Particles<D>::find(const std::string& name) const {
  for (std::size_t k = 0; k < fields_.size(); ++k)
    if (fields_[k].name == name) return static_cast<int>(k);
  return -1;
}

template <int D>
Field& Particles<D>::field(const std::string& name) {
  int k = find(name);
  if (k < 0) throw std::logic_error("no particle field '" + name + "'");
  return fields_[k];
}

template <int D>
const Field& Particles<D>::field(const std::string& name) const {
  int k = find(name);
  if (k < 0) throw std::logic_error("no particle field '" + name + "'");
  return fields_[k];
}

template <int D>
void Particles<D>::set_meaning(std::initializer_list<int> ks, unsigned phases, double pad_zz) {
  for (int k : ks)
    if (k >= 0) fields_[k].phases = phases, fields_[k].pad_zz = pad_zz;
}

template <int D>
int Particles<D>::add_field(const std::string& name, int ncomp, FieldType type, bool output) {
  int k = find(name);
  if (k >= 0) {
    if (fields_[k].ncomp != ncomp || fields_[k].type != type)
      throw std::logic_error("field '" + name + "' registered twice with different shapes");
    fields_[k].output = fields_[k].output || output;
    return k;
  }
  Field f;
  f.name = name;
  f.ncomp = ncomp;
  f.type = type;
  f.output = output;
  if (type == FieldType::Real)
    f.real.assign(n_ * ncomp, 0.0);
  else
    f.ints.assign(n_ * ncomp, 0);
  fields_.push_back(std::move(f));
  return static_cast<int>(fields_.size()) - 1;
}

template <int D>
void Particles<D>::resize(std::size_t n) {
  for (auto& f : fields_) {
    if (f.type == FieldType::Real)
      f.real.resize(n * f.ncomp, 0.0);
    else
      f.ints.resize(n * f.ncomp, 0);
  }
  n_ = n;
}

template <int D>
std::size_t Particles<D>::append(std::size_t n) {
  std::size_t first = n_;
  resize(n_ + n);
  auto ids = id();
  for (std::size_t i = first; i < n_; ++i) ids[i] = next_id_++;
  return first;
}

namespace {
template <class T>
void permute_vec(std::vector<T>& data, int nc, const std::vector<int>& order) {
  // Capacity as before: ghosts appended after a rebuild (MPI) then fit without reallocating.
  std::vector<T> out;
  out.reserve(std::max(data.capacity(), order.size() * nc));
  out.resize(order.size() * nc);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < order.size(); ++i)
    for (int c = 0; c < nc; ++c)
      out[i * nc + c] = data[static_cast<std::size_t>(order[i]) * nc + c];
  data.swap(out);
}
}  // namespace

template <int D>
void Particles<D>::permute(const std::vector<int>& order) {
  for (auto& f : fields_) {
    if (f.type == FieldType::Real)
      permute_vec(f.real, f.ncomp, order);
    else
      permute_vec(f.ints, f.ncomp, order);
  }
  n_ = order.size();
}

template <int D>
void Particles<D>::compact(const std::vector<int>& keep) {
  // keep is increasing, so keep[i] >= i: moving rows down in order never overwrites a row that
  // is still to be moved. No allocation (a rebuild under MPI does this every time).
  for (auto& f : fields_) {
    const std::size_t nc = f.ncomp;
    auto move_rows = [&](auto& data) {
      for (std::size_t i = 0; i < keep.size(); ++i)
        if (static_cast<std::size_t>(keep[i]) != i)
          std::copy_n(data.begin() + keep[i] * nc, nc, data.begin() + i * nc);
      data.resize(keep.size() * nc);
    };
    if (f.type == FieldType::Real)
      move_rows(f.real);
    else
      move_rows(f.ints);
  }
  n_ = keep.size();
}

template <int D>
std::size_t Particles<D>::remove(const std::vector<char>& flag) {
  std::vector<int> keep;
  keep.reserve(n_);
  for (std::size_t i = 0; i < n_; ++i)
    if (!flag[i]) keep.push_back(static_cast<int>(i));
  std::size_t removed = n_ - keep.size();
  if (removed) compact(keep);
  return removed;
}

template class Particles<2>;
template class Particles<3>;

}  // namespace monosph
