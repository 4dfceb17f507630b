#pragma once
// Composes the modules a scene enables. The only place that knows every module.
#include "core/simulation.hpp"

namespace monosph {

template <int D>
void assemble_modules(Simulation<D>& sim);

}  // namespace monosph
