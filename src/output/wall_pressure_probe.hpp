#pragma once
// Wall-pressure probe (`type: wall_pressure`): the mean pressure over a sensor on the face of a
// wall, as a pressure transducer measures it. The sensor is a segment of length `size` (2D) or a
// disc of diameter `size` (3D) centred at `center` on the wall face, perpendicular to `normal`
// (pointing from the wall into the fluid). At points spread evenly over the sensor (spacing at
// most dp/4, at least 10 of them) the pressure is the Shepard interpolation
//   p(x_s) = sum_j p_j V_j W(x_s - x_j) / sum_j V_j W(x_s - x_j),   V_j = m_j / rho_j,
// over the fluid particles (p_j their EOS pressure) and the wall-like particles (p_j their
// extrapolated Adami pressure p_w, Adami, Hu & Adams 2012, Eq. 27: the pressure the fluid sees
// there); the probe is the mean over the points (a point without any neighbour counts 0).
//
// Why this form: a sensor on the face sits where the fluid support is cut in half. A fluid-only
// Shepard sum there is the pressure about h/2 inside the fluid (on the floor of a hydrostatic
// tank rho g h/2 short); with the wall particles carrying p_w the pressure field continues
// through the face and the interpolation is centred on it (exact for the hydrostatic field on
// floor and side walls; tests/unit/test_wall_pressure.cpp). The published sensor data this is
// compared with (De Courcy et al. 2024 via TrixiParticles.jl, validation/dam_break_2d) are
// interpolated pressures averaged over points of a segment on the wall face, the same kind of
// quantity; the mean of the first-layer p_w alone would sit dp/2 behind the face and hold no
// particle at all for a sensor shorter than dp.
//
// At the start the probe checks that `center` lies on the face of `body` (the nearest particle
// of the body at most (sqrt(d)/2 + 0.05) dp away, the face being dp/2 from its outer layer:
// 0.76 dp in 2D, 0.92 dp in 3D) and that `normal`
// points away from the body (InputError naming the key). MPI: per-point sums over the owned
// particles, then over the ranks. Periodic images are not searched (a sensor on a wall).
#include <string>
#include <vector>

#include "core/simulation.hpp"

namespace monosph {

template <int D>
class WallPressureProbe {
 public:
  // `body`: index of the wall-like body the sensor sits on; `where`: "probes.list[k]".
  WallPressureProbe(Simulation<D>& sim, const ProbeSpec& spec, int body, const std::string& where);
  // The mean interpolated pressure over the sensor now (collective under MPI).
  double sample(Simulation<D>& sim) const;
  const std::vector<Vec<D>>& points() const { return pts_; }

 private:
  std::vector<Vec<D>> pts_;
  Vec<D> centre_;
  double reach_ = 0;  // particles farther than this from the centre take no part
  int kpw_ = -1;      // the fluid module's wall_pressure field
};

// Points spread over a sensor of length (2D) or diameter (3D) `size` centred at `c`,
// perpendicular to the unit vector `n`, at most `spacing` apart and at least 10 of them.
template <int D>
std::vector<Vec<D>> sensor_points(const Vec<D>& c, const Vec<D>& n, double size, double spacing);

}  // namespace monosph
