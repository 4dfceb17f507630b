#pragma once
// Thread-count independence: the same run on 1 and on 2 threads ends bit-identical.
#include <gtest/gtest.h>
#include <omp.h>

#include "core/simulation.hpp"

namespace monosph::test {

// The threads a parallel region gets now: a test that claims thread-count independence checks
// that its second run really had two.
inline int team_size() {
  int n = 0;
#pragma omp parallel
#pragma omp single
  n = omp_get_num_threads();
  return n;
}

// `make()` returns an initialised std::unique_ptr<Simulation<D>>; both runs take `steps` steps.
template <int D, class Make>
void expect_thread_independent(Make make, int steps) {
  const int before = omp_get_max_threads();
  auto run = [&](int threads) {
    omp_set_num_threads(threads);
    EXPECT_EQ(team_size(), threads);
    auto sim = make();
    for (int k = 0; k < steps; ++k) sim->advance();
    return sim;
  };
  auto a = run(1);
  auto b = run(2);
  omp_set_num_threads(before);
  auto& pa = a->particles();
  auto& pb = b->particles();
  ASSERT_EQ(pa.size(), pb.size());
  EXPECT_EQ(a->time(), b->time());
  for (std::size_t k = 0; k < pa.fields().size(); ++k) {
    EXPECT_EQ(pa.fields()[k].real, pb.fields()[k].real) << pa.fields()[k].name;
    EXPECT_EQ(pa.fields()[k].ints, pb.fields()[k].ints) << pa.fields()[k].name;
  }
}

}  // namespace monosph::test
