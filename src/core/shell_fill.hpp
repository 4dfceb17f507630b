// Body-fitted fill of a sphere or ring shape (`fill: shells`): concentric shells, each sampled at
// a spacing close to dp, so that the body's surface is round at particle scale instead of the
// lattice's facets (a lattice sphere is flat over a radius ~sqrt(R dp) at its poles).
#pragma once

#include <vector>

#include "scene/scene.hpp"

namespace monosph {

struct ShellPoint {
  Point x;
  double volume;  // the shell's volume divided by its point count (per unit depth in 2D)
};

// Points of `shape` (a sphere or ring; dim 2 or 3). Shells are (R - r_in) / n thick, n the
// nearest whole number to (R - r_in) / dp (at least 1), points at the shell mid-radii: 2D equal
// angles, 3D a Fibonacci spiral. The volumes sum to the shape's exact volume.
std::vector<ShellPoint> shell_points(const Shape& shape, int dim, double dp);
double shell_point_count(const Shape& shape, int dim, double dp);  // without allocating

}  // namespace monosph
