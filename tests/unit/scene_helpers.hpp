#pragma once
// Small scenes built in memory for unit tests.
#include <fmt/format.h>

#include <string>

#include "scene/scene.hpp"

namespace monosph::test {

// A D-dimensional box of fluid filling [0,lx]x[0,ly](x[0,lz]); periodic axes as given ("x, y").
inline Scene box_scene(int dim, double dp, double lx, double ly, double lz,
                       const std::string& periodic, double jitter,
                       const std::string& extra_body = "", const std::string& extra = "") {
  std::string mn = dim == 2 ? "[0, 0]" : "[0, 0, 0]";
  std::string mx =
      dim == 2 ? fmt::format("[{}, {}]", lx, ly) : fmt::format("[{}, {}, {}]", lx, ly, lz);
  std::string text = fmt::format(R"(
name: test
dimension: {0}
dp: {1}
domain: {{min: {2}, max: {3}, periodic: [{4}]}}
materials:
  water: {{density: 1000, sound_speed: 10}}
bodies:
  - name: block
    phase: fluid
    material: water
    shape: {{box: {{min: {2}, max: {3}}}}}
    jitter: {5}
    seed: 7
{6}
end_time: 1
{7}
)",
                                 dim, dp, mn, mx, periodic, jitter, extra_body, extra);
  return load_scene_text(text);
}

// A steel block (rho 7800, K 160 GPa, mu 80 GPa, dp = 0.01) filling [0, max] in the domain
// [-1, 1]^dim; `max` as "[lx, ly]" or "[lx, ly, lz]", `extra_body` more keys of the body.
inline Scene solid_block_scene(int dim, const std::string& max, double jitter, int seed,
                               const std::string& extra_body) {
  std::string text =
      fmt::format(R"(
name: block
dimension: {0}
dp: 0.01
domain: {{min: {1}, max: {2}}}
materials:
  steel: {{density: 7800, bulk_modulus: 160e9, shear_modulus: 80e9}}
bodies:
  - name: block
    phase: solid
    material: steel
    shape: {{box: {{min: {3}, max: {4}}}}}
    jitter: {5}
    seed: {6}
    {7}
end_time: 1
)",
                  dim, dim == 2 ? "[-1, -1]" : "[-1, -1, -1]", dim == 2 ? "[1, 1]" : "[1, 1, 1]",
                  dim == 2 ? "[0, 0]" : "[0, 0, 0]", max, jitter, seed, extra_body);
  return load_scene_text(text);
}

}  // namespace monosph::test
