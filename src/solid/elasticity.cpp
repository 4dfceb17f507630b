#include "elasticity.hpp"

namespace monosph {

template <int D>
Mat<D> tensile_part(const Mat<D>& sigma) {
  using M = Eigen::Matrix<double, D, D>;
  Eigen::SelfAdjointEigenSolver<M> es;
  es.computeDirect(0.5 * (M(sigma) + M(sigma).transpose()));
  Eigen::Matrix<double, D, 1> lam = es.eigenvalues().cwiseMax(0.0);
  return Mat<D>(es.eigenvectors() * lam.asDiagonal() * es.eigenvectors().transpose());
}

template Mat<2> tensile_part<2>(const Mat<2>&);
template Mat<3> tensile_part<3>(const Mat<3>&);

}  // namespace monosph
