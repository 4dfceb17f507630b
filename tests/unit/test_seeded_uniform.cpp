// uniform(seed, stream): a deterministic number in [0, 1) from a hash of its two arguments,
// available in every expression (scene/expression.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <set>

#include "core/types.hpp"
#include "scene/expression.hpp"

namespace monosph {
namespace {

TEST(SeededUniform, SameArgumentsGiveTheSameNumberBitForBit) {
  for (int s = 0; s < 50; ++s)
    for (int k = 0; k < 5; ++k) {
      const double a = seeded_uniform(s, k), b = seeded_uniform(s, k);
      EXPECT_EQ(std::memcmp(&a, &b, sizeof a), 0);
    }
  // Arguments are rounded to whole numbers: 3.2 and 2.8 are seed 3.
  EXPECT_EQ(seeded_uniform(3.2, 1), seeded_uniform(3, 1));
  EXPECT_EQ(seeded_uniform(2.8, 1), seeded_uniform(3, 1));
  // Pinned values: splitmix64(splitmix64(a) + b) >> 11, times 2^-53 (the same on every machine).
  EXPECT_EQ(seeded_uniform(0, 0), 0x1.4e0dba5e9a32fp-1);
  EXPECT_EQ(seeded_uniform(1, 2), 0x1.79b3b7692ce60p-1);
}

TEST(SeededUniform, LiesInTheUnitIntervalAndItsMeanIsAHalf) {
  double sum = 0;
  const int n = 10000;
  for (int i = 0; i < n; ++i) {
    const double u = seeded_uniform(i, 1);
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u;
  }
  EXPECT_NEAR(sum / n, 0.5, 0.01);
  double sum2 = 0;  // along the stream too
  for (int i = 0; i < n; ++i) sum2 += seeded_uniform(7, i);
  EXPECT_NEAR(sum2 / n, 0.5, 0.01);
}

TEST(SeededUniform, DifferentSeedsAndStreamsDiffer) {
  std::set<double> seen;
  for (int s = -20; s < 20; ++s)
    for (int k = 0; k < 20; ++k) seen.insert(seeded_uniform(s, k));
  EXPECT_EQ(seen.size(), 40u * 20u);
  EXPECT_NE(seeded_uniform(1, 2), seeded_uniform(2, 1));  // not symmetric
}

TEST(SeededUniform, NonFiniteOrHugeArgumentsGiveNaN) {
  EXPECT_TRUE(std::isnan(seeded_uniform(NAN, 1)));
  EXPECT_TRUE(std::isnan(seeded_uniform(1, INFINITY)));
  EXPECT_TRUE(std::isnan(seeded_uniform(1e300, 1)));
}

TEST(SeededUniform, EveryExpressionHasIt) {
  Expression e("uniform(seed, 2) + 0*x", "test", {{"seed", 5}});
  EXPECT_EQ(e(0.3), seeded_uniform(5, 2));
  EXPECT_EQ(constant_expression("10*uniform(seed,1)", "k", {{"seed", 3}}),
            10 * seeded_uniform(3, 1));
  try {
    Expression bad("uniform(1)", "here");
    ADD_FAILURE() << "one argument accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("here: invalid expression"), std::string::npos);
  }
}

}  // namespace
}  // namespace monosph
