#pragma once
// Pair terms of particle shifting (src/fluid; docs/theory.md, "Sheared flow without a free
// surface"). i is the particle, j its neighbour, gw = grad_i W_ij, Vj the volume of j; du is the
// shift velocity (particles move at v + du), zero on wall-like particles.
#include "core/types.hpp"

namespace monosph {

// Transport velocity (Adami, Hu & Adams 2013, JCP 241:292; the background-pressure term of their
// transport velocity): du_i = -(dt/2) (p_b / m_i) sum_j (V_i^2 + V_j^2) grad W_ij. One pair's
// sum term (V_i^2 + V_j^2) grad W_ij.
template <int D>
Vec<D> transport_pair(double Vi, double Vj, const Vec<D>& gw) {
  return (Vi * Vi + Vj * Vj) * gw;
}

// Consistent shifting (Sun, Colagrossi, Marrone, Antuono & Zhang 2019, CMAME 348:912; the
// du-terms of their continuity and momentum equations, shared/reference/equations.md 3.4). The
// particle moves at v + du, so its density and velocity change by the convective terms
//   d rho_i/dt += sum_j [(rho_j du_j + rho_i du_i) - rho_i (du_j - du_i)] . grad W_ij V_j
//              = div(rho du) - rho div(du) = du . grad rho,
//   d v_i/dt   += sum_j [(v_j (x) du_j + v_i (x) du_i) - v_i (x) (du_j - du_i)] . grad W_ij V_j
//              = div(v (x) du) - v div(du) = (du . grad) v.
template <int D>
double ale_continuity_pair(double rhoi, double rhoj, const Vec<D>& dui, const Vec<D>& duj,
                           const Vec<D>& gw, double Vj) {
  return Vj * (rhoj * duj + rhoi * dui - rhoi * (duj - dui)).dot(gw);
}

template <int D>
Vec<D> ale_momentum_pair(const Vec<D>& vi, const Vec<D>& vj, const Vec<D>& dui, const Vec<D>& duj,
                         const Vec<D>& gw, double Vj) {
  return Vj * (vj * duj.dot(gw) + vi * (dui.dot(gw) - (duj - dui).dot(gw)));
}

}  // namespace monosph
