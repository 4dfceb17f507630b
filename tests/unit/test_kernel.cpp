#include <gtest/gtest.h>

#include <cmath>

#include "core/kernel.hpp"

using namespace monosph;

namespace {

template <int D>
double lattice_sum(const Kernel<D>& w, double dp) {
  const int n = static_cast<int>(std::ceil(w.radius() / dp)) + 1;
  double s = 0;
  if constexpr (D == 2) {
    for (int a = -n; a <= n; ++a)
      for (int b = -n; b <= n; ++b) s += dp * dp * w.w(dp * std::hypot(a, b));
  } else {
    for (int a = -n; a <= n; ++a)
      for (int b = -n; b <= n; ++b)
        for (int c = -n; c <= n; ++c)
          s += dp * dp * dp * w.w(dp * std::sqrt(a * a + b * b + c * c));
  }
  return s;
}

// Integral of W over the plane/space by radial quadrature (midpoint rule, fine).
template <int D>
double integral(const Kernel<D>& w) {
  const int n = 200000;
  const double dr = w.radius() / n;
  double s = 0;
  for (int k = 0; k < n; ++k) {
    const double r = (k + 0.5) * dr;
    s += (D == 2 ? 2 * M_PI * r : 4 * M_PI * r * r) * w.w(r) * dr;
  }
  return s;
}

const KernelType kAll[] = {KernelType::CubicSpline, KernelType::WendlandC2,
                           KernelType::QuinticSpline};

}  // namespace

TEST(Kernel, IntegratesToOne) {
  for (auto t : kAll) {
    EXPECT_NEAR(integral(Kernel<2>(t, 0.013)), 1.0, 1e-8) << kernel_name(t);
    EXPECT_NEAR(integral(Kernel<3>(t, 0.013)), 1.0, 1e-8) << kernel_name(t);
  }
}

TEST(Kernel, CubicSplineMatchesMMBEq1) {
  // W(0) = k/h^d * (8 - 4) with k = 5/(14 pi) in 2D and 1/(4 pi) in 3D.
  const double h = 0.5;
  EXPECT_NEAR(Kernel<2>(KernelType::CubicSpline, h).w(0), 5.0 / (14 * M_PI) / (h * h) * 4, 1e-14);
  EXPECT_NEAR(Kernel<3>(KernelType::CubicSpline, h).w(0), 1.0 / (4 * M_PI) / (h * h * h) * 4,
              1e-14);
  EXPECT_NEAR(Kernel<2>(KernelType::CubicSpline, h).w(1.5 * h), 5.0 / (14 * M_PI) / (h * h) * 0.125,
              1e-14);
  EXPECT_EQ(Kernel<2>(KernelType::CubicSpline, h).w(2 * h), 0.0);
}

TEST(Kernel, PartitionOfUnityOnLatticeAtH13dp) {
  // |sum_j V_j W_ij - 1| < 1e-3 inside a body for h = 1.3 dp (cubic spline, MMB).
  const double dp = 0.01;
  EXPECT_LT(std::abs(lattice_sum(Kernel<2>(KernelType::CubicSpline, 1.3 * dp), dp) - 1), 1e-3);
  // In 3D the cubic spline at h = 1.3 dp sums to 1 + 2.74e-3 on a cubic lattice (measured).
  EXPECT_LT(std::abs(lattice_sum(Kernel<3>(KernelType::CubicSpline, 1.3 * dp), dp) - 1), 3e-3);
  // The wider kernels at their usual smoothing lengths (Wendland C2: 1.2e-3 in 2D, measured).
  EXPECT_LT(std::abs(lattice_sum(Kernel<2>(KernelType::WendlandC2, 2.0 * dp), dp) - 1), 2e-3);
  EXPECT_LT(std::abs(lattice_sum(Kernel<3>(KernelType::WendlandC2, 2.0 * dp), dp) - 1), 2e-3);
  EXPECT_LT(std::abs(lattice_sum(Kernel<2>(KernelType::QuinticSpline, 1.0 * dp), dp) - 1), 1e-3);
  EXPECT_LT(std::abs(lattice_sum(Kernel<3>(KernelType::QuinticSpline, 1.0 * dp), dp) - 1), 1e-3);
}

TEST(Kernel, GradientFactorIsDerivativeOverR) {
  for (auto t : kAll) {
    Kernel<2> w2(t, 0.7);
    Kernel<3> w3(t, 0.7);
    for (double r = 0.01; r < w2.radius(); r += 0.0137) {
      const double e = 1e-6;
      EXPECT_NEAR(w2.f(r) * r, (w2.w(r + e) - w2.w(r - e)) / (2 * e), 1e-6)
          << kernel_name(t) << " r=" << r;
      EXPECT_NEAR(w3.f(r) * r, (w3.w(r + e) - w3.w(r - e)) / (2 * e), 1e-6)
          << kernel_name(t) << " r=" << r;
    }
    // Finite limit at r -> 0.
    EXPECT_NEAR(w2.f(0.0), w2.f(1e-7), 1e-4 * std::abs(w2.f(0.0)) + 1e-9) << kernel_name(t);
  }
}

TEST(Kernel, BranchFreeCubicSplineMatchesTheReference) {
  // wf_cubic (the pair-list fast path) against w() and f() on both sides of q = 1 and 2.
  const double h = 0.013;
  Kernel<2> w2(KernelType::CubicSpline, h);
  Kernel<3> w3(KernelType::CubicSpline, h);
  for (double q = 0.0; q < 2.0; q += 0.0137) {
    const double r = q * h;
    double a, b;
    w2.wf_cubic(r * r, a, b);
    EXPECT_NEAR(a, w2.w(r), 1e-12 * w2.w(0)) << q;
    EXPECT_NEAR(b, w2.f(r), 1e-9 * std::abs(w2.f(0))) << q;
    w3.wf_cubic(r * r, a, b);
    EXPECT_NEAR(a, w3.w(r), 1e-12 * w3.w(0)) << q;
    EXPECT_NEAR(b, w3.f(r), 1e-9 * std::abs(w3.f(0))) << q;
  }
}
