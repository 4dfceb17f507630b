#pragma once
// SPH kernels: value W(r) and gradient factor F(r) = W'(r)/r, so that grad_i W_ij = F(r) (x_i -
// x_j).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/types.hpp"

namespace monosph {

enum class KernelType { CubicSpline, WendlandC2, QuinticSpline };

KernelType kernel_from_name(const std::string& name);  // throws InputError
const char* kernel_name(KernelType t);

template <int D>
class Kernel {
 public:
  Kernel() = default;
  Kernel(KernelType type, double h) : type_(type), h_(h) {
    constexpr double pi = std::numbers::pi;
    const double hd = std::pow(h, D);
    switch (type) {
      case KernelType::CubicSpline:  // Mohseni-Mofidi & Bierwisch 2020, Eq. 1
        k_ = (D == 2 ? 5.0 / (14.0 * pi) : 1.0 / (4.0 * pi)) / hd;
        support_ = 2.0;
        break;
      case KernelType::WendlandC2:  // Wendland 1995, C2 ("quintic Wendland"), support 2h
        k_ = (D == 2 ? 7.0 / (4.0 * pi) : 21.0 / (16.0 * pi)) / hd;
        support_ = 2.0;
        break;
      case KernelType::QuinticSpline:  // Morris 1997 quintic spline, support 3h
        k_ = (D == 2 ? 7.0 / (478.0 * pi) : 1.0 / (120.0 * pi)) / hd;
        support_ = 3.0;
        break;
    }
    inv_h_ = 1.0 / h;
  }

  KernelType type() const { return type_; }
  double h() const { return h_; }
  double radius() const { return support_ * h_; }

  double w(double r) const {
    const double q = r * inv_h_;
    switch (type_) {
      case KernelType::CubicSpline: {
        if (q >= 2.0) return 0.0;
        const double a = 2.0 - q;
        double s = a * a * a;
        if (q < 1.0) {
          const double b = 1.0 - q;
          s -= 4.0 * b * b * b;
        }
        return k_ * s;
      }
      case KernelType::WendlandC2: {
        if (q >= 2.0) return 0.0;
        const double a = 1.0 - 0.5 * q;
        const double a2 = a * a;
        return k_ * a2 * a2 * (1.0 + 2.0 * q);
      }
      case KernelType::QuinticSpline: {
        if (q >= 3.0) return 0.0;
        auto p5 = [](double t) { return t * t * t * t * t; };
        double s = p5(3.0 - q);
        if (q < 2.0) s -= 6.0 * p5(2.0 - q);
        if (q < 1.0) s += 15.0 * p5(1.0 - q);
        return k_ * s;
      }
    }
    return 0.0;
  }

  // F(r) = W'(r)/r (finite at r = 0).
  double f(double r) const {
    const double q = r * inv_h_;
    const double c = k_ * inv_h_ * inv_h_;  // dW/dr / r = (k/h^d) dS/dq / (h q h)
    switch (type_) {
      case KernelType::CubicSpline: {
        if (q >= 2.0) return 0.0;
        // dS/dq = -3(2-q)^2 + 12(1-q)^2 (q<1); -3(2-q)^2 (q>=1)
        if (q < 1.0) return c * (-12.0 + 9.0 * q);  // (dS/dq)/q simplified for q<1
        const double a = 2.0 - q;
        return c * (-3.0 * a * a / q);
      }
      case KernelType::WendlandC2: {
        if (q >= 2.0) return 0.0;
        const double a = 1.0 - 0.5 * q;
        return c * (-5.0 * a * a * a);
      }
      case KernelType::QuinticSpline: {
        if (q >= 3.0) return 0.0;
        auto p4 = [](double t) { return t * t * t * t; };
        if (q < 1e-12) return c * -120.0;  // limit of S'(q)/q = S''(0)
        double s = -5.0 * p4(3.0 - q);
        if (q < 2.0) s += 30.0 * p4(2.0 - q);
        if (q < 1.0) s -= 75.0 * p4(1.0 - q);
        return c * s / q;
      }
    }
    return 0.0;
  }

  double dw(double r) const { return f(r) * r; }

  // W and F of the cubic spline without branches on q (the pair pass evaluates millions of them
  // per step, with q on either side of 1 at random): with a = max(2 - q, 0), b = max(1 - q, 0),
  // S = a^3 - 4 b^3 and S'(q)/q = (-3 a^2 + 12 b^2)/q = 9q - 12 for q < 1.
  void wf_cubic(double r2, double& wv, double& fv) const {
    // Written with arithmetic instead of max/?: so that the compiler emits no branches:
    // ramp(t) = (t + |t|)/2 = max(t, 0) exactly; the select is a product with 0 or 1.
    auto ramp = [](double t) { return 0.5 * (t + std::abs(t)); };
    const double q = std::sqrt(r2) * inv_h_;
    const double a = ramp(2.0 - q), b = ramp(1.0 - q);
    wv = k_ * (a * a * a - 4.0 * b * b * b);
    const double c = k_ * inv_h_ * inv_h_;
    const double inner = 9.0 * q - 12.0, outer = -3.0 * a * a / (1.0 + ramp(q - 1.0));
    const double in = static_cast<double>(q < 1.0);
    fv = c * (outer + in * (inner - outer));
  }

  // W and F together from the squared distance (one root, no work beyond the support).
  void wf(double r2, double& wv, double& fv) const {
    const double rs = radius();
    if (r2 >= rs * rs) {
      wv = fv = 0.0;
      return;
    }
    const double r = std::sqrt(r2);
    wv = w(r);
    fv = f(r);
  }

 private:
  KernelType type_ = KernelType::CubicSpline;
  double h_ = 1.0, inv_h_ = 1.0, k_ = 0.0, support_ = 2.0;
};

}  // namespace monosph
