#pragma once
// Small scenes built in memory for unit tests.
#include <fmt/format.h>

#include <string>

#include "core/scene.hpp"

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

}  // namespace monosph::test
