#include <gtest/gtest.h>

#include <random>
#include <set>
#include <tuple>

#include "core/neighbours.hpp"

using namespace monosph;

namespace {

// Brute force: every (i, j, image) with |x_i - x_j - shift| < rc, over all periodic images.
template <int D>
std::set<std::tuple<int, int, long>> brute(Particles<D>& p, const Domain<D>& dom, double rc) {
  std::set<std::tuple<int, int, long>> out;
  auto x = p.x();
  const int nimg = D == 2 ? 9 : 27;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = 0; j < p.size(); ++j)
      for (int c = 0; c < nimg; ++c) {
        Vec<D> sh;
        int r = c;
        bool ok = true;
        for (int a = 0; a < D; ++a) {
          int s = r % 3 - 1;
          r /= 3;
          if (s != 0 && !dom.periodic[a]) ok = false;
          sh[a] = s * (dom.hi[a] - dom.lo[a]);
        }
        if (!ok || (i == j && c == (nimg - 1) / 2)) continue;
        if ((x[i] - x[j] - sh).norm() < rc) out.insert({int(i), int(j), c});
      }
  return out;
}

template <int D>
void check(std::array<bool, D> periodic, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  Domain<D> dom;
  for (int a = 0; a < D; ++a) dom.lo[a] = -0.3 * a, dom.hi[a] = dom.lo[a] + 1.0 + 0.2 * a;
  dom.periodic = periodic;
  Particles<D> p;
  p.append(D == 2 ? 700 : 900);
  auto x = p.x();
  for (auto& xi : x)
    for (int a = 0; a < D; ++a) xi[a] = dom.lo[a] + u(rng) * (dom.hi[a] - dom.lo[a]);
  // A few particles exactly on the bounds.
  x[0] = dom.lo;
  x[1] = dom.hi;
  if (!dom.periodic[0]) x[1][0] = dom.hi[0];
  for (int a = 0; a < D; ++a)
    if (dom.periodic[a]) x[1][a] = dom.hi[a];  // wraps to lo
  const double rc = 0.2, skin = 0.05;
  Neighbours<D> nb;
  nb.configure(dom, rc, skin);
  ASSERT_EQ(nb.build(p, seed % 2 == 0), -1);
  x = p.x();
  auto ref = brute(p, dom, rc);
  std::set<std::tuple<int, int, long>> got;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t k = nb.begin(i); k < nb.end(i); ++k) {
      const int j = nb.nbr(k);
      const Vec<D> r = nb.rij(x[i], x[j], k);
      EXPECT_LT(r.norm(), rc + skin + 1e-12);
      if (r.norm() < rc) {
        // Recover the image code from the shift vector.
        long c = 0, pw = 1;
        for (int a = 0; a < D; ++a) {
          const double len = dom.hi[a] - dom.lo[a];
          c += (std::lround(nb.shift(k)[a] / len) + 1) * pw;
          pw *= 3;
        }
        EXPECT_TRUE(got.insert({int(i), j, c}).second) << "duplicate pair";
      }
    }
  EXPECT_EQ(got, ref);
}

}  // namespace

TEST(Neighbours, MatchBruteForce2D) {
  check<2>({false, false}, 1);
  check<2>({true, false}, 2);
  check<2>({false, true}, 3);
  check<2>({true, true}, 4);
}

TEST(Neighbours, MatchBruteForce3D) {
  check<3>({false, false, false}, 5);
  check<3>({true, false, false}, 6);
  check<3>({false, true, true}, 7);
  check<3>({true, true, true}, 8);
}

TEST(Neighbours, ReorderKeepsEveryField) {
  Particles<2> p;
  p.append(500);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  auto x = p.x();
  auto m = p.m();
  for (std::size_t i = 0; i < p.size(); ++i) x[i] = Vec<2>(u(rng), u(rng)), m[i] = 1000.0 + i;
  Domain<2> dom;
  dom.periodic = {true, true};
  Neighbours<2> nb;
  nb.configure(dom, 0.1, 0.02);
  nb.build(p, true);
  auto id = p.id();
  m = p.m();
  for (std::size_t i = 0; i < p.size(); ++i) EXPECT_EQ(m[i], 1000.0 + id[i]);
}

TEST(Neighbours, PeriodicAxisTooShortIsAnInputError) {
  Domain<2> dom;
  dom.periodic = {true, false};
  Neighbours<2> nb;
  EXPECT_THROW(nb.configure(dom, 0.3, 0.1), InputError);
}

TEST(Neighbours, ParticleOutsideNonPeriodicDomainIsReported) {
  Domain<2> dom;
  Particles<2> p;
  p.append(3);
  p.x()[0] = Vec<2>(0.5, 0.5);
  p.x()[1] = Vec<2>(0.5, 1.5);
  p.x()[2] = Vec<2>(0.2, 0.5);
  Neighbours<2> nb;
  nb.configure(dom, 0.1, 0.01);
  EXPECT_EQ(nb.build(p, false), 1);
}
