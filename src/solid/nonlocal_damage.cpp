#include "solid/nonlocal_damage.hpp"

#include <algorithm>
#include <cmath>

namespace monosph {

template <int D>
void NonlocalAverage<D>::bin(Simulation<D>& sim, std::span<const double> length, double cell) {
  // Cells at least l wide on the domain's grid, over the box of the averaged particles (whole
  // periodic axes); at most about 8 cells per particle (wider cells: the same sums, slower).
  const auto& dom = sim.neighbours().domain();
  const auto x = sim.particles().x();
  const std::size_t n = sim.owned();
  Vec<D> lo = dom.hi, hi = dom.lo;
  std::size_t members = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (length[i] > 0) lo = lo.cwiseMin(x[i]), hi = hi.cwiseMax(x[i]), ++members;
  std::size_t total = 0;
  for (double c = cell; total == 0 || total > 8 * members + 1024; c *= 2) {
    total = 1;
    for (int a = 0; a < D; ++a) {
      const int all = std::max(1, int(std::floor(dom.length()[a] / c)));
      size_[a] = dom.length()[a] / all;
      int k0 = 0, k1 = all - 1;
      if (!dom.periodic[a]) {
        k0 = std::clamp(int(std::floor((lo[a] - dom.lo[a]) / size_[a])), 0, all - 1);
        k1 = std::clamp(int(std::floor((hi[a] - dom.lo[a]) / size_[a])), k0, all - 1);
      }
      lo_[a] = dom.lo[a] + k0 * size_[a];
      nc_[a] = k1 - k0 + 1;
      total *= std::size_t(nc_[a]);
    }
  }
  start_.assign(total + 1, 0);
  cell_of_.assign(n, -1);
  for (std::size_t i = 0; i < n; ++i) {
    if (length[i] <= 0) continue;
    int c = 0;
    for (int a = D - 1; a >= 0; --a) {
      const int k = std::clamp(int(std::floor((x[i][a] - lo_[a]) / size_[a])), 0, nc_[a] - 1);
      c = c * nc_[a] + k;
    }
    cell_of_[i] = c;
    ++start_[c + 1];
  }
  for (std::size_t c = 0; c < total; ++c) start_[c + 1] += start_[c];
  items_.resize(start_[total]);
  fill_.assign(start_.begin(), start_.end() - 1);  // kept: no allocation per step
  for (std::size_t i = 0; i < n; ++i)
    if (cell_of_[i] >= 0) items_[fill_[cell_of_[i]]++] = int(i);
}

template <int D>
void NonlocalAverage<D>::average(Simulation<D>& sim, std::span<const double> length,
                                 std::span<const double> inc, std::vector<double>& out) {
  const std::size_t n = sim.owned();
  out.assign(n, 0.0);
  double lmax = 0;
  for (std::size_t i = 0; i < n; ++i) lmax = std::max(lmax, length[i]);
  if (lmax <= 0) return;
  bin(sim, length, lmax);
  // The particles with an increment, by cell (a subsequence of items_: the same order of sums).
  const std::size_t cells = start_.size() - 1;
  act_start_.assign(cells + 1, 0);
  for (std::size_t i = 0; i < n; ++i)
    if (cell_of_[i] >= 0 && inc[i] > 0) ++act_start_[cell_of_[i] + 1];
  for (std::size_t c = 0; c < cells; ++c) act_start_[c + 1] += act_start_[c];
  act_items_.resize(act_start_[cells]);
  for (std::size_t c = 0, q = 0; c < cells; ++c)
    for (std::size_t k = start_[c]; k < start_[c + 1]; ++k)
      if (inc[items_[k]] > 0) act_items_[q++] = items_[k];
  auto& p = sim.particles();
  const auto x = p.x();
  const auto bd = p.body();
  const auto m = p.m();
  const auto rho = p.rho();
  const auto& dom = sim.neighbours().domain();
  const Vec<D> len = dom.length();
  constexpr int kNear = D == 2 ? 9 : 27;
#pragma omp parallel for schedule(dynamic, 256)
  for (std::size_t i = 0; i < n; ++i) {
    if (cell_of_[i] < 0) continue;
    // The cells around i's (wrapped along periodic axes, each once).
    std::array<int, kNear> near;
    int count = 0;
    bool any = false;
    std::array<int, D> ci;
    for (int a = 0, c = cell_of_[i]; a < D; ++a) ci[a] = c % nc_[a], c /= nc_[a];
    for (int o = 0; o < kNear; ++o) {
      int c = 0;
      bool inside = true;
      for (int a = D - 1, r = o; a >= 0; --a) {
        const int off = (a == 0 ? r : r / (a == 1 ? 3 : 9)) % 3 - 1;
        int k = ci[a] + off;
        if (dom.periodic[a]) k = (k + nc_[a]) % nc_[a];
        inside = inside && k >= 0 && k < nc_[a];
        c = c * nc_[a] + k;
      }
      if (!inside || std::find(near.begin(), near.begin() + count, c) != near.begin() + count)
        continue;
      near[count++] = c;
      any = any || act_start_[c + 1] > act_start_[c];
    }
    if (!any) continue;
    const double l2 = length[i] * length[i];
    auto weight = [&](int j) {  // w(r_ij) V_j, minimum image along periodic axes
      Vec<D> d = x[j] - x[i];
      for (int a = 0; a < D; ++a)
        if (dom.periodic[a]) d[a] -= len[a] * std::rint(d[a] / len[a]);
      return bell_weight(d.squaredNorm(), l2) * m[j] / rho[j];
    };
    double num = 0, den = 0;
    for (int q = 0; q < count; ++q)  // the particles with an increment first
      for (std::size_t k = act_start_[near[q]]; k < act_start_[near[q] + 1]; ++k)
        if (bd[act_items_[k]] == bd[i]) num += weight(act_items_[k]) * inc[act_items_[k]];
    if (num == 0) continue;  // none within l: no need of the normalisation
    for (int q = 0; q < count; ++q)
      for (std::size_t k = start_[near[q]]; k < start_[near[q] + 1]; ++k)
        if (bd[items_[k]] == bd[i]) den += weight(items_[k]);
    out[i] = num / den;
  }
}

template class NonlocalAverage<2>;
template class NonlocalAverage<3>;

}  // namespace monosph
