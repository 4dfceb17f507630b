// Particle container: registered fields, removal with compaction, permutation.
#include <gtest/gtest.h>

#include "core/particles.hpp"

using namespace monosph;

TEST(Particles, RemovalCompactsEveryFieldAndKeepsOrder) {
  Particles<3> p;
  const int kT = p.add_field("temperature", 1);
  const int kS = p.add_field("stress", 9);
  p.append(10);
  for (std::size_t i = 0; i < 10; ++i) {
    p.x()[i] = Vec<3>(i, 2.0 * i, 3.0 * i);
    p.view<double>(kT)[i] = 100.0 + i;
    p.view<Mat3>(kS)[i] = Mat3::Constant(double(i));
  }
  std::vector<char> flag(10, 0);
  flag[0] = flag[4] = flag[9] = 1;
  EXPECT_EQ(p.remove(flag), 3u);
  ASSERT_EQ(p.size(), 7u);
  const std::int64_t expect[] = {1, 2, 3, 5, 6, 7, 8};
  for (std::size_t i = 0; i < 7; ++i) {
    const auto id = p.id()[i];
    EXPECT_EQ(id, expect[i]);
    EXPECT_EQ(p.x()[i][2], 3.0 * id);
    EXPECT_EQ(p.view<double>(kT)[i], 100.0 + id);
    EXPECT_EQ(p.view<Mat3>(kS)[i](2, 1), double(id));
  }
  // New particles get fresh ids, never reused.
  p.append(2);
  EXPECT_EQ(p.id()[7], 10);
  EXPECT_EQ(p.id()[8], 11);
}

TEST(Particles, FieldsRegisterOnceWithOneShape) {
  Particles<2> p;
  const int a = p.add_field("damage", 1);
  EXPECT_EQ(p.add_field("damage", 1, FieldType::Real, true), a);
  EXPECT_TRUE(p.field(a).output);
  EXPECT_THROW(p.add_field("damage", 2), std::logic_error);
  EXPECT_FALSE(p.has("plastic_strain"));
}
