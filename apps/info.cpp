#include "info.hpp"

#include <fmt/format.h>

#include "assemble.hpp"
#include "core/scene.hpp"

namespace monosph {

namespace {
template <int D>
int info_impl(const Scene& scene) {
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
               bi.phase == kFluid  ? "fluid"
               : bi.phase == kWall ? "wall"
                                   : "solid",
               scene.materials[bi.material].name, count[b]);
  }
  fmt::print("total      {} particles\n", p.size());
  std::string mods;
  for (const auto& m : sim.modules()) mods += (mods.empty() ? "" : ", ") + m->name();
  fmt::print("modules    {}\n", mods);
  std::size_t bytes = 0, per = 0;
  for (const auto& f : p.fields()) per += f.ncomp * 8;
  bytes = per * p.size();
  // Verlet pairs: volume of the (support + skin) sphere over dp^D, 5 bytes each (index + shift).
  const double rc = (scene.h_factor * (scene.kernel == KernelType::QuinticSpline ? 3 : 2) +
                     scene.skin_factor * scene.h_factor);
  const double pairs = D == 2 ? 3.14159 * rc * rc : 4.18879 * rc * rc * rc;
  const double nbytes = pairs * 5 * p.size();
  fmt::print("fields     {} per particle: ", per);
  for (const auto& f : p.fields()) fmt::print("{} ", f.name);
  fmt::print(
      "\nmemory     about {:.1f} MB (fields {:.1f} MB, neighbour lists {:.1f} MB, ~{:.0f} pairs "
      "per particle)\n",
      (bytes + nbytes) / 1e6, bytes / 1e6, nbytes / 1e6, pairs);
  return 0;
}
}  // namespace

int print_info(const std::string& path, const std::vector<std::string>& overrides) {
  Scene scene = load_scene_file(path, overrides);
  return scene.dimension == 2 ? info_impl<2>(scene) : info_impl<3>(scene);
}

}  // namespace monosph
