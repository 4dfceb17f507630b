#pragma once
// The initial temperature of every particle (Material::initial_temperature of its body), for the
// modules that own a temperature field.
#include "core/simulation.hpp"

namespace monosph {

template <int D>
void set_initial_temperatures(Simulation<D>& sim, int field) {
  auto& p = sim.particles();
  auto T = p.template view<double>(field);
  auto bd = p.body();
  for (std::size_t i = 0; i < p.size(); ++i) {
    const BodyInfo& b = sim.bodies()[bd[i]];
    T[i] = sim.materials()[b.material].initial_temperature(b.temperature);
  }
}

}  // namespace monosph
