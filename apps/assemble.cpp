#include "assemble.hpp"

#include <algorithm>

#include "core/sph_equations.hpp"
#include "rigid/rigid_surface_module.hpp"
#include "solid/solid_module.hpp"

namespace monosph {

template <int D>
void assemble_modules(Simulation<D>& sim) {
  const auto& mods = sim.scene().modules;
  auto enabled = [&](const char* m) {
    return std::find(mods.begin(), mods.end(), m) != mods.end();
  };
  // The shared Eulerian SPH equations are always on (first: the others read their sums).
  sim.add_module(std::make_unique<SphEquations<D>>(sim, enabled("solid")));
  if (enabled("solid")) sim.add_module(std::make_unique<SolidModule<D>>(sim));
  if (enabled("rigid")) sim.add_module(std::make_unique<RigidSurfaceModule<D>>(sim));
}

template void assemble_modules<2>(Simulation<2>&);
template void assemble_modules<3>(Simulation<3>&);

}  // namespace monosph
