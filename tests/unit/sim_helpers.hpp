#pragma once
// A simulation built from scene text with every module the scene enables, initialised; and one
// of its modules by type.
#include <memory>
#include <stdexcept>
#include <string>

#include "assemble.hpp"
#include "scene/scene.hpp"

namespace monosph::test {

template <int D>
std::unique_ptr<Simulation<D>> build(const std::string& text) {
  auto sim = std::make_unique<Simulation<D>>(load_scene_text(text));
  assemble_modules(*sim);
  sim->create_particles();
  sim->init();
  return sim;
}

// The InputError message of loading `text` ("" when it loads).
inline std::string load_error(const std::string& text) {
  try {
    load_scene_text(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

template <class M, int D>
M& module(Simulation<D>& sim) {
  for (auto& m : sim.modules())
    if (auto* c = dynamic_cast<M*>(m.get())) return *c;
  throw std::logic_error("no such module");
}

}  // namespace monosph::test
