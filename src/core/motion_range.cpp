#include "core/motion_range.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <span>
#include <vector>

namespace monosph {

template <int D>
std::string untouched_bodies_warning(Simulation<D>& sim) {
  const auto& bodies = sim.bodies();
  const std::size_t nb = bodies.size();
  const auto& mods = sim.scene().modules;  // bodies in contact meet without the SPH equations
  if (std::find(mods.begin(), mods.end(), "solid_contact") != mods.end()) return "";
  // Per body: -lo (D), hi (D), largest speed; reduced with max over the ranks.
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> r(nb * (2 * D + 1), -inf);
  auto& p = sim.particles();
  auto x = p.x();
  auto v = p.v();
  auto bd = p.body();
  for (std::size_t i = 0; i < sim.owned(); ++i) {
    double* b = &r[bd[i] * (2 * D + 1)];
    for (int a = 0; a < D; ++a)
      b[a] = std::max(b[a], -x[i][a]), b[D + a] = std::max(b[D + a], x[i][a]);
    b[2 * D] = std::max(b[2 * D], v[i].norm());
  }
  sim.comm().max(std::span<double>(r));
  const double rest = std::max(0.0, sim.scene().end_time - sim.time());
  auto range = [&](std::size_t b, int a, bool hi) {
    const double* q = &r[b * (2 * D + 1)];
    const double reach = q[2 * D] * rest + sim.dp();  // plus the particles' own size
    return hi ? q[D + a] + reach : -q[a] - reach;
  };
  std::string first;
  int count = 0;
  for (std::size_t b = 0; b < nb; ++b)
    for (std::size_t c = b + 1; c < nb; ++c) {
      if (bodies[b].phase != kSolid || bodies[c].phase != kSolid) continue;
      if (bodies[b].group == bodies[c].group) continue;
      if (!(r[b * (2 * D + 1) + 2 * D] > -inf && r[c * (2 * D + 1) + 2 * D] > -inf)) continue;
      bool overlap = true;
      for (int a = 0; a < D; ++a)
        overlap = overlap && range(b, a, false) < range(c, a, true) &&
                  range(c, a, false) < range(b, a, true);
      if (!overlap) continue;
      if (++count == 1) first = fmt::format("'{}' and '{}'", bodies[b].name, bodies[c].name);
    }
  if (count == 0) return "";
  return fmt::format(
      "solid bodies {}{} may meet but will pass through each other: different continua do not "
      "interact and the scene has no solid_contact section",
      first, count > 1 ? fmt::format(" (and {} more pairs)", count - 1) : "");
}

template std::string untouched_bodies_warning<2>(Simulation<2>&);
template std::string untouched_bodies_warning<3>(Simulation<3>&);

}  // namespace monosph
