#include "assemble.hpp"

#include <algorithm>

#include "core/sph_equations.hpp"
#include "fluid/fluid_module.hpp"
#include "rigid/rigid_surface_module.hpp"
#include "solid/solid_module.hpp"

namespace monosph {

template <int D>
void assemble_modules(Simulation<D>& sim) {
  const auto& mods = sim.scene().modules;
  auto enabled = [&](const char* m) {
    return std::find(mods.begin(), mods.end(), m) != mods.end();
  };
  // The shared Eulerian SPH equations (first: the solid module reads their sums) run for solids,
  // and for fluids only in a scene without the delta-plus fluid module. A fluid-only scene
  // carries none of their fields.
  const bool any_solid = std::any_of(sim.bodies().begin(), sim.bodies().end(),
                                     [](const BodyInfo& b) { return b.phase == kSolid; });
  if (any_solid || !enabled("fluid")) {
    auto sph = std::make_unique<SphEquations<D>>(sim, enabled("solid"));
    sph->set_solids_only(enabled("fluid"));
    sim.add_module(std::move(sph));
  }
  if (enabled("fluid")) sim.add_module(std::make_unique<FluidModule<D>>(sim));
  if (enabled("solid")) sim.add_module(std::make_unique<SolidModule<D>>(sim));
  if (enabled("rigid")) sim.add_module(std::make_unique<RigidSurfaceModule<D>>(sim));
}

template void assemble_modules<2>(Simulation<2>&);
template void assemble_modules<3>(Simulation<3>&);

}  // namespace monosph
