#include <gtest/gtest.h>
#include <fstream>
#include "core/sph_equations.hpp"
#include "solid/solid_module.hpp"
#include "assemble.hpp"
using namespace monosph;
TEST(Scratch, Patch) {
  Scene s = load_scene_file("/work/main/cases/patch_test/scene.yaml", {"bodies.0.hourglass.xi=10", "bodies.0.jitter=0"});
  Simulation<2> sim(s);
  assemble_modules(sim);
  sim.create_particles();
  sim.init();
  auto& p = sim.particles();
  for (double tt : {2.0, 6.0, 10.0}) {
    while (sim.time() < tt) sim.advance();
    std::ofstream out("/tmp/patch_" + std::to_string(int(tt)) + ".dat");
    auto dis = p.view<double>("disorder");
    for (size_t i = 0; i < p.size(); ++i) out << p.x()[i][0] << " " << p.x()[i][1] << " " << dis[i] << " " << p.p()[i] << "\n";
  }
}
