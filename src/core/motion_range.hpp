#pragma once
// Solid bodies that may meet but can neither interact nor touch: two solid bodies of different
// continua (no shared SPH equations) in a scene without `solid_contact` whose motion ranges
// overlap pass through each other. The motion range of a body is the box of its particles now,
// widened on every side by its largest speed times the time left to end_time.
#include <string>

#include "core/simulation.hpp"

namespace monosph {

// The warning text naming the first such pair (empty if none). Collective under MPI.
template <int D>
std::string untouched_bodies_warning(Simulation<D>& sim);

}  // namespace monosph
