#pragma once
// Composes the modules a scene enables. The only place that knows every module.
#include "core/simulation.hpp"

namespace monosph {

// Registers every module's scene keys (scene/module_keys.hpp); call once before reading a scene.
void register_modules();

template <int D>
void assemble_modules(Simulation<D>& sim);

}  // namespace monosph
