#pragma once
// The chip thickness ratio of a cut (probe `chip_ratio`, scene/scene_probes.cpp read_chip): the
// chip's thickness over the uncut chip thickness `size`, by `method` layer, section or flow.
#include "core/simulation.hpp"

namespace monosph {

// The chip in the window of `spec` of a surface moved by `displacement` and moving at
// `velocity` (for a tool: -vc).
template <int D>
double chip_ratio(Simulation<D>& sim, const ProbeSpec& spec, const Vec<D>& displacement,
                  const Vec<D>& velocity);

}  // namespace monosph
