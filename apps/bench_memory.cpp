// Memory bandwidth of the machine, for reading the thread ratios of `bench --suite`: the STREAM
// triad a = b + s c (McCalpin 1995; 24 bytes per element, best of several repeats) over arrays in
// the caches and in main memory. Pair loops over arrays larger than the last-level cache gain
// from a second thread no more than the memory does.
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <vector>

#include "bench.hpp"

namespace monosph {

double triad_gb_per_s(int threads, std::size_t bytes) {
  const std::size_t n = std::max<std::size_t>(bytes / 24, 1024);
  std::unique_ptr<double[]> a(new double[n]), b(new double[n]), c(new double[n]);
  double* __restrict pa = a.get();
  const double* __restrict pb = b.get();
  const double* __restrict pc = c.get();
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::size_t i = 0; i < n; ++i) pa[i] = 0, b[i] = 1, c[i] = 2;  // first touch, as used
  // Repeats: about 4 GB moved in all (at least 5), the fastest counts.
  const int repeats = static_cast<int>(std::clamp<std::size_t>(4000000000 / (24 * n), 5, 2000));
  double best = 1e300;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
#pragma omp parallel for schedule(static) num_threads(threads)
    for (std::size_t i = 0; i < n; ++i) pa[i] = pb[i] + 1.5 * pc[i];
    best = std::min(best,
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return best > 0 ? 24.0 * double(n) / best / 1e9 : 0.0;
}

std::vector<Bandwidth> memory_bandwidth(const std::vector<int>& threads) {
  std::vector<Bandwidth> out;
  for (std::size_t bytes : {std::size_t(8) << 20, std::size_t(512) << 20})
    for (int t : threads) out.push_back({t, bytes, triad_gb_per_s(t, bytes)});
  return out;
}

}  // namespace monosph
