#include "core/neighbours.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

namespace monosph {

template <int D>
void Neighbours<D>::configure(const Domain<D>& dom, double cutoff, double skin) {
  dom_ = dom;
  cutoff_ = cutoff;
  skin_ = skin;
  cell_ = cutoff + skin;
  const char* axis = "xyz";
  for (int a = 0; a < D; ++a) {
    const double len = dom.hi[a] - dom.lo[a];
    nc_[a] = std::max(1, static_cast<int>(std::floor(len / cell_)));
    if (dom.periodic[a] && nc_[a] < 3)
      throw InputError(
          std::string("domain: periodic axis ") + axis[a] + " is " + std::to_string(len) +
          " long; it must be at least 3 x (kernel support + skin) = " + std::to_string(3 * cell_));
  }
  for (int c = 0; c < kShifts; ++c) {
    int r = c;
    for (int a = 0; a < D; ++a) {
      int s = r % 3 - 1;
      r /= 3;
      shift_[c][a] = s * (dom.hi[a] - dom.lo[a]);
    }
  }
}

template <int D>
std::array<int, D> Neighbours<D>::cell_of(const Vec<D>& x) const {
  std::array<int, D> c;
  for (int a = 0; a < D; ++a) {
    const double len = dom_.hi[a] - dom_.lo[a];
    int k = static_cast<int>(std::floor((x[a] - dom_.lo[a]) / len * nc_[a]));
    c[a] = std::clamp(k, 0, nc_[a] - 1);
  }
  return c;
}

template <int D>
std::uint32_t Neighbours<D>::cell_index(const Vec<D>& x) const {
  const auto c = cell_of(x);
  std::size_t k = 0, stride = 1;
  for (int a = 0; a < D; ++a) k += c[a] * stride, stride *= nc_[a];
  return static_cast<std::uint32_t>(k);
}

template <int D>
long Neighbours<D>::wrap(Particles<D>& p) const {
  auto x = p.x();
  const long n = static_cast<long>(p.size());
  long bad = n;  // the first particle outside: the smallest index over the threads
#pragma omp parallel for reduction(min : bad) schedule(static)
  for (long i = 0; i < n; ++i) {
    for (int a = 0; a < D; ++a) {
      const double len = dom_.hi[a] - dom_.lo[a];
      if (dom_.periodic[a]) {
        if (x[i][a] < dom_.lo[a] || x[i][a] >= dom_.hi[a]) {
          x[i][a] -= std::floor((x[i][a] - dom_.lo[a]) / len) * len;
          if (x[i][a] >= dom_.hi[a]) x[i][a] = dom_.lo[a];
        }
      } else if (!(x[i][a] >= dom_.lo[a] && x[i][a] <= dom_.hi[a])) {
        bad = std::min(bad, i);
      }
    }
  }
  return bad < n ? bad : -1;
}

template <int D>
void Neighbours<D>::sort_by_cell(Particles<D>& p) const {
  auto x = p.x();
  std::size_t ncell = 1;
  for (int a = 0; a < D; ++a) ncell *= nc_[a];
  std::vector<std::uint32_t> key(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) key[i] = cell_index(x[i]);
  std::vector<int> order(p.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return key[a] < key[b]; });
  p.permute(order);
}

template <int D>
long Neighbours<D>::build(Particles<D>& p, bool reorder, std::size_t rows) {
  auto t0 = std::chrono::steady_clock::now();
  const std::size_t n = p.size();
  long bad = wrap(p);
  if (bad >= 0) return bad;
  auto x = p.x();

  std::size_t ncell = 1;
  std::array<std::size_t, D> stride;
  for (int a = 0; a < D; ++a) {
    stride[a] = ncell;
    ncell *= nc_[a];
  }
  std::vector<std::uint32_t> cell(n);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) cell[i] = cell_index(x[i]);
  // Counting sort by cell.
  std::vector<std::size_t> cstart(ncell + 1, 0);
  for (std::size_t i = 0; i < n; ++i) ++cstart[cell[i] + 1];
  for (std::size_t c = 0; c < ncell; ++c) cstart[c + 1] += cstart[c];
  std::vector<int> sorted(n);
  {
    std::vector<std::size_t> fill(cstart.begin(), cstart.end() - 1);
    for (std::size_t i = 0; i < n; ++i) sorted[fill[cell[i]]++] = static_cast<int>(i);
  }
  if (reorder) {
    p.permute(sorted);
    x = p.x();
    std::vector<std::uint32_t> c2(n);
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      c2[i] = cell[sorted[i]];
      sorted[i] = static_cast<int>(i);
    }
    cell.swap(c2);
  }

  const double rc2 = cell_ * cell_;
  std::array<std::array<int, D>, kShifts> offs;
  for (int c = 0; c < kShifts; ++c) {
    int r = c;
    for (int a = 0; a < D; ++a) {
      offs[c][a] = r % 3 - 1;
      r /= 3;
    }
  }
  // Visits the neighbours of i (two passes: count, then fill).
  auto visit = [&](std::size_t i, auto&& emit) {
    std::array<int, D> ci;
    {
      std::size_t k = cell[i];
      for (int a = 0; a < D; ++a) {
        ci[a] = static_cast<int>(k % nc_[a]);
        k /= nc_[a];
      }
    }
    for (int o = 0; o < kShifts; ++o) {
      std::size_t nk = 0;
      int code = 0, pw = 1;
      bool skip = false;
      for (int a = 0; a < D; ++a) {
        int c = ci[a] + offs[o][a];
        int s = 0;
        if (c < 0) {
          if (!dom_.periodic[a]) {
            skip = true;
            break;
          }
          c += nc_[a];
          s = -1;
        } else if (c >= nc_[a]) {
          if (!dom_.periodic[a]) {
            skip = true;
            break;
          }
          c -= nc_[a];
          s = 1;
        }
        // A single cell along a non-periodic axis: offsets +-1 map onto nothing.
        nk += c * stride[a];
        code += (s + 1) * pw;
        pw *= 3;
      }
      if (skip) continue;
      const Vec<D>& sh = shift_[code];
      for (std::size_t q = cstart[nk]; q < cstart[nk + 1]; ++q) {
        const int j = sorted[q];
        if (static_cast<std::size_t>(j) == i && code == (kShifts - 1) / 2) continue;
        const Vec<D> r = x[i] - x[j] - sh;
        if (r.squaredNorm() < rc2) emit(j, code);
      }
    }
  };

  start_.assign(n + 1, 0);
  rows = std::min(rows, n);
  // One pass over the cells: each thread collects the rows of its block in order, then copies
  // them to their place -- the list a count pass and a fill pass would give.
  if (buffers_.size() < static_cast<std::size_t>(omp_get_max_threads()))
    buffers_.resize(omp_get_max_threads());
#pragma omp parallel
  {
    const std::size_t t = omp_get_thread_num(), nt = omp_get_num_threads();
    const std::size_t lo = rows * t / nt, hi = rows * (t + 1) / nt;
    RowBuffer& b = buffers_[t];
    b.j.clear(), b.code.clear();
    for (std::size_t i = lo; i < hi; ++i) {
      const std::size_t k0 = b.j.size();
      visit(i, [&](int j, int code) {
        b.j.push_back(j);
        b.code.push_back(static_cast<std::uint8_t>(code));
      });
      start_[i + 1] = b.j.size() - k0;
    }
#pragma omp barrier
#pragma omp single
    {
      for (std::size_t i = 0; i < n; ++i) start_[i + 1] += start_[i];
      nbr_.resize(start_[n]);
      code_.resize(start_[n]);
    }
    std::copy(b.j.begin(), b.j.end(), nbr_.begin() + start_[lo]);
    std::copy(b.code.begin(), b.code.end(), code_.begin() + start_[lo]);
  }
  x_build_.resize(n);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) x_build_[i] = x[i];
  ++builds_;
  build_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return -1;
}

template <int D>
bool Neighbours<D>::needs_rebuild(Particles<D>& p) const {
  if (x_build_.size() != p.size()) return true;
  auto x = p.x();
  const double lim2 = 0.25 * skin_ * skin_;
  int flag = 0;
#pragma omp parallel for reduction(max : flag) schedule(static)
  for (std::size_t i = 0; i < p.size(); ++i)
    if ((x[i] - x_build_[i]).squaredNorm() > lim2) flag = 1;
  return flag != 0;
}

template class Neighbours<2>;
template class Neighbours<3>;

}  // namespace monosph
