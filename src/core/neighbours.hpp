#pragma once
// Cell list with periodic axes (wrapped cell indices + a shift vector per pair) and a Verlet
// list with skin, rebuilt when a particle has moved more than half the skin. Full lists: every
// particle sees all its neighbours, so pair loops write only their own particle.
#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/particles.hpp"

namespace monosph {

template <int D>
struct Domain {
  Vec<D> lo = Vec<D>::Zero(), hi = Vec<D>::Ones();
  std::array<bool, D> periodic{};
  Vec<D> length() const { return hi - lo; }
};

template <int D>
class Neighbours {
 public:
  static constexpr int kShifts = D == 2 ? 9 : 27;

  // Throws InputError if a periodic axis is shorter than 3 cells.
  void configure(const Domain<D>& dom, double cutoff, double skin);

  // Wraps positions on periodic axes, bins particles and builds the pair lists. With reorder,
  // particles are first permuted into cell order (all fields). Returns -1, or the index of a
  // particle outside a non-periodic bound (nothing built then).
  // Only the first `rows` particles get a list (MPI: ghosts are neighbours but need none: the
  // values their owners compute replace theirs).
  long build(Particles<D>& p, bool reorder,
             std::size_t rows = std::numeric_limits<std::size_t>::max());
  bool needs_rebuild(Particles<D>& p) const;
  // Wraps positions on periodic axes; returns -1 or the first particle outside a non-periodic
  // bound.
  long wrap(Particles<D>& p) const;
  // Permutes the particles into cell order (MPI runs sort the owned ones before ghosts exist).
  void sort_by_cell(Particles<D>& p) const;

  const Domain<D>& domain() const { return dom_; }
  double cutoff() const { return cutoff_; }
  double skin() const { return skin_; }
  std::size_t pairs() const { return nbr_.size(); }
  int builds() const { return builds_; }
  void set_builds(int n) { builds_ = n; }  // a restart: the rebuilds before its checkpoint
  double build_seconds() const { return build_seconds_; }

  // Pair range of particle i: k in [begin(i), end(i)), neighbour j = nbr(k).
  std::size_t begin(std::size_t i) const { return start_[i]; }
  std::size_t end(std::size_t i) const { return start_[i + 1]; }
  int nbr(std::size_t k) const { return nbr_[k]; }
  // x_i - x_j for pair k, with the periodic image shift.
  Vec<D> rij(const Vec<D>& xi, const Vec<D>& xj, std::size_t k) const {
    return xi - xj - shift_[code_[k]];
  }
  const Vec<D>& shift(std::size_t k) const { return shift_[code_[k]]; }
  // Raw arrays for hot loops: neighbour of slot k, its shift code, the shift of each code.
  const int* nbr_data() const { return nbr_.data(); }
  const std::uint8_t* code_data() const { return code_.data(); }
  const std::array<Vec<D>, kShifts>& shifts() const { return shift_; }

 private:
  std::array<int, D> cell_of(const Vec<D>& x) const;
  std::uint32_t cell_index(const Vec<D>& x) const;  // cell_of flattened, x fastest
  Domain<D> dom_;
  double cutoff_ = 0, skin_ = 0, cell_ = 0;
  std::array<int, D> nc_{};
  std::array<Vec<D>, kShifts> shift_;
  std::vector<std::size_t> start_;
  std::vector<int> nbr_;
  std::vector<std::uint8_t> code_;
  std::vector<Vec<D>> x_build_;
  // One thread's rows during a build (kept: no allocation per build). A cache line each: two
  // threads' vector ends in one line made every push_back a transfer of the line between the
  // cores, and the build on two threads slower than on one.
  struct alignas(64) RowBuffer {
    std::vector<int> j;
    std::vector<std::uint8_t> code;
  };
  std::vector<RowBuffer> buffers_;
  int builds_ = 0;
  double build_seconds_ = 0;
};

}  // namespace monosph
