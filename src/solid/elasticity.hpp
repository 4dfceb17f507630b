#pragma once
// Hypoelastic deviatoric stress with the Jaumann rate (MMB Eq. 14-16), plane strain in 2D: the
// full 3x3 deviator is carried, the velocity gradient is padded with zeros (D_zz = 0).
#include "core/types.hpp"

namespace monosph {

// Pads a DxD velocity gradient to 3x3.
template <int D>
inline Mat3 pad33(const Mat<D>& g) {
  Mat3 r = Mat3::Zero();
  r.template topLeftCorner<D, D>() = g;
  return r;
}

// dS/dt = 2 mu (Edot - tr(Edot)/3 I) + Omega S - S Omega   (MMB Eq. 14-15; L = grad v, row = v)
inline Mat3 jaumann_rate(const Mat3& S, const Mat3& L, double mu) {
  const Mat3 e = 0.5 * (L + L.transpose());
  const Mat3 w = 0.5 * (L - L.transpose());
  return 2.0 * mu * (e - e.trace() / 3.0 * Mat3::Identity()) + w * S - S * w;
}

// Objective update of S over dt: the deviatoric rate of MMB Eq. 14 plus the Jaumann spin
// terms, integrated with the Hughes-Winget rotation Q = (I - dt/2 W)^-1 (I + dt/2 W), which is
// exactly orthogonal: a pure spin rotates S without changing its invariants.
inline Mat3 update_deviatoric(const Mat3& S, const Mat3& L, double mu, double dt) {
  const Eigen::Matrix3d e = 0.5 * (L + L.transpose());
  const Eigen::Matrix3d w = 0.5 * (L - L.transpose());
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d q;
  if (w(0, 2) == 0.0 && w(1, 2) == 0.0) {  // spin about z (all of 2D): closed-form Cayley rotation
    const double a = 0.5 * dt * w(1, 0), c = (1 - a * a) / (1 + a * a), s = 2 * a / (1 + a * a);
    q << c, -s, 0, s, c, 0, 0, 0, 1;
  } else {
    // The same Cayley map in closed form for a skew A (A^3 = -|a|^2 A, a its axial vector):
    // (I - A)^-1 (I + A) = I + 2 (A + A^2) / (1 + |a|^2).
    const Eigen::Matrix3d A = 0.5 * dt * w;
    const double a2 = A(2, 1) * A(2, 1) + A(0, 2) * A(0, 2) + A(1, 0) * A(1, 0);
    q = I + (2.0 / (1.0 + a2)) * (A + A * A);
  }
  const Eigen::Matrix3d s = Eigen::Matrix3d(S) + dt * 2.0 * mu * (e - e.trace() / 3.0 * I);
  return Mat3(q * s * q.transpose());
}

// von Mises equivalent stress sqrt(3/2 S:S) (MMB Eq. 22).
inline double von_mises(const Mat3& S) {
  return std::sqrt(1.5 * S.cwiseProduct(S).sum());
}

// Artificial stress tensor R (MMB Eq. 19-20): the tensile principal part of Sigma,
// R = Q diag(max(sigma_a, 0)) Q^T with the eigenvectors of Sigma as columns of Q.
template <int D>
Mat<D> tensile_part(const Mat<D>& sigma);

}  // namespace monosph
