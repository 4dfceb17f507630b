// Jaumann-rate elasticity (MMB Eq. 14-15) and the artificial stress tensor (Eq. 19-20).
#include <gtest/gtest.h>

#include <random>

#include "solid/elasticity.hpp"

using namespace monosph;

namespace {
Mat3 random_deviator(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  Mat3 s;
  for (int r = 0; r < 3; ++r)
    for (int c = r; c < 3; ++c) s(r, c) = s(c, r) = 1e6 * u(rng);
  s -= s.trace() / 3 * Mat3::Identity();
  return s;
}
double j2(const Mat3& s) {
  return 0.5 * s.cwiseProduct(s).sum();
}
double j3(const Mat3& s) {
  return s.determinant();
}
}  // namespace

TEST(Jaumann, RigidRotationBy90DegreesKeepsInvariants) {
  // A pre-stressed point spun about z by 90 degrees in 1000 steps: S -> R S R^T.
  const Mat3 s0 = random_deviator(1);
  const double omega = 2.0, t_end = M_PI / 2 / omega, dt = t_end / 1000;
  Mat3 L = Mat3::Zero();
  L(0, 1) = -omega, L(1, 0) = omega;  // v = omega x (x, y): grad v
  Mat3 s = s0;
  for (int k = 0; k < 1000; ++k) s = update_deviatoric(s, L, 80e9, dt);
  EXPECT_NEAR(j2(s), j2(s0), 1e-6 * j2(s0));
  EXPECT_NEAR(j3(s), j3(s0), 1e-6 * std::abs(j3(s0)));
  Mat3 R = Mat3::Zero();
  R(0, 1) = -1, R(1, 0) = 1, R(2, 2) = 1;
  EXPECT_LT((s - R * s0 * R.transpose()).norm(), 1e-6 * s0.norm());
}

TEST(Jaumann, RigidRotationAboutATiltedAxisKeepsInvariants) {
  // The same about the axis n = (1, 2, 2)/3 (the closed-form 3D Cayley map): S -> R S R^T with
  // R the rotation by 90 degrees about n (Rodrigues: R = I + sin K + (1 - cos) K^2).
  const Mat3 s0 = random_deviator(2);
  const Vec3 n(1.0 / 3, 2.0 / 3, 2.0 / 3);
  const double omega = 3.0, t_end = M_PI / 2 / omega, dt = t_end / 1000;
  Mat3 K;
  K << 0, -n.z(), n.y(), n.z(), 0, -n.x(), -n.y(), n.x(), 0;
  const Mat3 L = omega * K;  // v = omega n x x
  Mat3 s = s0;
  for (int k = 0; k < 1000; ++k) s = update_deviatoric(s, L, 80e9, dt);
  EXPECT_NEAR(j2(s), j2(s0), 1e-9 * j2(s0));
  EXPECT_NEAR(j3(s), j3(s0), 1e-9 * std::abs(j3(s0)));
  const Mat3 R = Mat3::Identity() + K + K * K;
  EXPECT_LT((s - R * s0 * R.transpose()).norm(), 1e-6 * s0.norm());
  EXPECT_GT((s - s0).norm(), 0.1 * s0.norm());  // it did turn
}

TEST(Jaumann, RateMatchesMMBEq14) {
  const Mat3 s = random_deviator(2);
  Mat3 L;
  L << 0.1, -0.3, 0.0, 0.5, -0.2, 0.0, 0.0, 0.0, 0.0;
  const double mu = 26.5e9, dt = 1e-12;
  const Mat3 e = 0.5 * (L + L.transpose()), w = 0.5 * (L - L.transpose());
  const Mat3 expected = 2 * mu * (e - e.trace() / 3 * Mat3::Identity()) - s * w + w * s;
  const Mat3 rate = (update_deviatoric(s, L, mu, dt) - s) / dt;
  EXPECT_LT((rate - expected).norm(), 1e-5 * expected.norm());
  EXPECT_LT((jaumann_rate(s, L, mu) - expected).norm(), 1e-9 * expected.norm());
}

TEST(Jaumann, PlaneStrainKeepsTheOutOfPlaneDeviator) {
  // Uniaxial in-plane stretch rate: S_zz = -(S_xx + S_yy) is non-zero and the trace stays zero.
  Mat3 L = Mat3::Zero();
  L(0, 0) = 1.0;
  Mat3 s = Mat3::Zero();
  for (int k = 0; k < 100; ++k) s = update_deviatoric(s, L, 1e9, 1e-6);
  EXPECT_NEAR(s.trace(), 0.0, 1e-6);
  EXPECT_NEAR(s(2, 2), -2.0 / 3.0 * 1e9 * 1e-4, 1e-3);
  EXPECT_GT(von_mises(s), 0.0);
}

TEST(ArtificialStress, KeepsTheTensilePrincipalPart) {
  Mat<2> sig;
  sig << 3.0, 1.0, 1.0, -2.0;  // one tensile, one compressive principal stress
  const Mat<2> r = tensile_part<2>(sig);
  const Eigen::Matrix2d sd = sig;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(sd);
  const double s1 = es.eigenvalues()[1];
  const Eigen::Vector2d n1 = es.eigenvectors().col(1);
  EXPECT_LT((Eigen::Matrix2d(r) - s1 * n1 * n1.transpose()).norm(), 1e-12);
  Mat<3> comp = -Mat<3>::Identity();
  EXPECT_EQ(tensile_part<3>(comp).norm(), 0.0);
}
