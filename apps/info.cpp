#include "info.hpp"

#include <fmt/format.h>

#include "assemble.hpp"
#include "core/memory.hpp"
#include "scene/scene.hpp"
#include "scene/scene_dump.hpp"

namespace monosph {

namespace {

const char* phase_name(Phase ph) {
  switch (ph) {
    case kFluid:
      return "fluid";
    case kSolid:
      return "solid";
    case kRigid:
      return "rigid";
    case kWall:
      return "wall";
  }
  return "?";
}

template <int D>
int info_impl(const Scene& scene) {
  const std::size_t rss0 = resident_bytes();  // program and libraries
  Simulation<D> sim(scene);
  assemble_modules(sim);
  sim.create_particles();
  auto& p = sim.particles();
  std::vector<std::size_t> count(sim.bodies().size(), 0);
  for (auto b : p.body()) ++count[b];
  fmt::print("scene      {} ({}D, dp = {:g} m, h = {:g} m, kernel {})\n", scene.name, D, scene.dp,
             scene.h(), kernel_name(scene.kernel));
  fmt::print("end time   {:g} s\n", scene.end_time);
  for (std::size_t b = 0; b < count.size(); ++b) {
    const auto& bi = sim.bodies()[b];
    fmt::print("body       {:<16} {:<6} material {:<12} {:>10} particles\n", bi.name,
               phase_name(static_cast<Phase>(bi.phase)), scene.materials[bi.material].name,
               count[b]);
  }
  fmt::print("total      {} particles\n", p.size());
  std::string mods;
  for (const auto& m : sim.modules()) mods += (mods.empty() ? "" : ", ") + m->name();
  fmt::print("modules    {}\n", mods);
  std::size_t per = 0, out_per = 0;
  for (const auto& f : p.fields()) {
    per += f.ncomp * 8;
    if (f.output) out_per += 3 * f.ncomp * 8;  // padded to 3D
  }
  fmt::print("fields     {} bytes per particle: ", per);
  for (const auto& f : p.fields()) fmt::print("{} ", f.name);
  fmt::print("\n");
  // Memory as measured: the run's set-up (first neighbour build, pair lists, module caches) and
  // one step are done here, and the heap they hold is counted. A frame being written holds its
  // arrays twice more (VTK copy, compressed base64 text).
  const std::size_t fields = per * p.size();
  try {
    sim.init(false);
    sim.advance();
  } catch (const RunAborted&) {  // the memory is allocated by then; the run will say the rest
  }
  const std::size_t heap = heap_in_use();
  const std::size_t frame = 2 * out_per * p.size();
  const double pairs = double(sim.neighbours().pairs()) / std::max<std::size_t>(1, p.size());
  fmt::print(
      "memory     about {:.1f} MB for a run on one rank (particle fields {:.1f} MB, neighbour "
      "lists and module data {:.1f} MB, {:.0f} pairs per particle; frame output {:.1f} MB; "
      "program {:.1f} MB)\n",
      (rss0 + heap + frame) / 1e6, fields / 1e6, (heap - std::min(heap, fields)) / 1e6, pairs,
      frame / 1e6, rss0 / 1e6);
  return 0;
}
}  // namespace

int print_info(const std::string& path, const std::vector<std::string>& overrides, bool config) {
  Scene scene = load_scene_file(path, overrides);
  if (config) {
    fmt::print("{}\n", scene_config(scene).dump(1));
    return 0;
  }
  return scene.dimension == 2 ? info_impl<2>(scene) : info_impl<3>(scene);
}

}  // namespace monosph
