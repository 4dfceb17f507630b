#include "assemble.hpp"

#include "core/sph_equations.hpp"

namespace monosph {

template <int D>
void assemble_modules(Simulation<D>& sim) {
  // The shared Eulerian SPH equations are always on; physics modules follow in later steps.
  sim.add_module(std::make_unique<SphEquations<D>>(sim, false));
}

template void assemble_modules<2>(Simulation<2>&);
template void assemble_modules<3>(Simulation<3>&);

}  // namespace monosph
