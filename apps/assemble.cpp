#include "assemble.hpp"

#include <algorithm>

#include "core/sph_equations.hpp"
#include "coupling/contact_module.hpp"
#include "coupling/coupling_keys.hpp"
#include "coupling/lubrication_module.hpp"
#include "coupling/solid_contact_module.hpp"
#include "fluid/fluid_keys.hpp"
#include "fluid/fluid_module.hpp"
#include "heat/heat_keys.hpp"
#include "heat/heat_module.hpp"
#include "rigid/cluster_keys.hpp"
#include "rigid/cluster_module.hpp"
#include "rigid/rigid_surface_module.hpp"
#include "solid/solid_keys.hpp"
#include "solid/solid_module.hpp"

namespace monosph {

// The keys each module reads (in this order: the order of their messages).
void register_modules() {
  register_module_keys(fluid_keys());
  register_module_keys(solid_keys());
  register_module_keys(cluster_keys());
  register_module_keys(heat_keys());
  register_module_keys(contact_keys());
  register_module_keys(lubrication_keys());
  register_module_keys(solid_contact_keys());
}

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
  const bool any_rigid = std::any_of(sim.bodies().begin(), sim.bodies().end(),
                                     [](const BodyInfo& b) { return b.phase == kRigid; });
  // Multi-rate stepping sub-steps the solids (fast modules) inside the steps of the rest.
  if (sim.scene().multi_rate && !(any_solid && (enabled("fluid") || any_rigid)))
    throw InputError(
        "time_step.multi_rate: needs solid bodies beside a fluid or rigid grains (the solids "
        "are sub-stepped inside the steps of the rest)");
  if (any_solid || !enabled("fluid")) {
    auto sph = std::make_unique<SphEquations<D>>(sim, enabled("solid"));
    // Rigid-cluster particles move with their cluster: no SPH equations for them.
    sph->set_solids_only(enabled("fluid") || any_rigid);
    sim.add_module(std::move(sph));
  }
  if (enabled("fluid")) sim.add_module(std::make_unique<FluidModule<D>>(sim));
  if (enabled("solid")) sim.add_module(std::make_unique<SolidModule<D>>(sim));
  if (enabled("rigid")) sim.add_module(std::make_unique<RigidSurfaceModule<D>>(sim));
  if (enabled("contact")) sim.add_module(std::make_unique<ContactModule<D>>(sim));
  if (enabled("solid_contact")) sim.add_module(std::make_unique<SolidContactModule<D>>(sim));
  if (enabled("lubrication")) sim.add_module(std::make_unique<LubricationModule<D>>(sim));
  if (HeatModule<D>::needed(sim)) sim.add_module(std::make_unique<HeatModule<D>>(sim));
  // Last: it sums every force its particles received (fluid, contact, surfaces, body force).
  if (enabled("clusters")) sim.add_module(std::make_unique<ClusterModule<D>>(sim));
}

template void assemble_modules<2>(Simulation<2>&);
template void assemble_modules<3>(Simulation<3>&);

}  // namespace monosph
