#pragma once
// The bad-input corpus: valid base scenes, each case one edit of a base, and the check every
// case must pass: exit code 2, one line naming the key, no crash, no hang (a time limit), no
// summary.json that claims "completed".
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "../validation/run_helpers.hpp"

namespace monosph::test {

// A tank with water, a clamped steel plate, boundary conditions, probes, references and checks.
inline const char* const kFluid = R"yaml(name: corpus
description: a tank with water and a clamped plate
dimension: 2
dp: 0.01
kernel: {type: cubic_spline, h_factor: 1.3}
domain: {min: [0, 0], max: [0.4, 0.3]}
neighbours: {skin: 0.3, reorder_every: 1}
variables: {speed: 0.1}
materials:
  water: {density: 1000, sound_speed: 10, viscosity: 1.0e-3}
  steel: {density: 7800, bulk_modulus: 1.6e11, shear_modulus: 8.0e10}
bodies:
  - name: tank
    phase: wall
    material: water
    shape: {difference: [{box: {min: [0, 0], max: [0.4, 0.3]}}, {box: {min: [0.03, 0.03], max: [0.37, 0.3]}}]}
  - name: water
    phase: fluid
    material: water
    shape: {box: {min: [0.03, 0.03], max: [0.2, 0.15]}}
    initial: {density: "1000", velocity: ["speed", "0"]}
    density_diffusion: {delta: 0.1}
  - name: plate
    phase: solid
    material: steel
    shape: {box: {min: [0.25, 0.03], max: [0.3, 0.2]}}
    hourglass: {xi: 1}
boundary_conditions:
  - {name: clamp, type: fixed, region: {box: {min: [0.25, 0.03], max: [0.3, 0.05]}}}
  - {name: push, type: velocity, body: water, velocity: ["speed*t", free]}
body_force: [0, -9.81]
end_time: 1.0e-5
time_step: {cfl: 0.3, force_factor: 0.25}
guards: {max_mach: 0.5, min_distance: 0.1}
output: {every: 5.0e-6, checkpoint_every: 0}
probes:
  every: 0
  list:
    - {name: ke, type: kinetic_energy}
    - {name: mass, type: total_mass, body: water}
    - {name: mode, type: integral, field: density, weight: "cos(x)"
}
    - {name: tip, type: tracked, field: position.y, point: [0.27, 0.2]}
reference:
  - {name: final_mass, value: 1, probe: mass, measure: final}
checks:
  - {name: mass_kept, probe: mass, measure: drift, max: 0.01}
)yaml";

// Rigid grains (clusters per part) over an eroding aluminium target in oil, a rigid floor,
// contact and lubrication.
inline const char* const kGrains = R"yaml(name: grains
dimension: 2
dp: 0.001
domain: {min: [0, 0], max: [0.05, 0.05]}
materials:
  iron: {preset: iron}
  oil: {density: 900, sound_speed: 20, viscosity: 0.01}
  al: {preset: Al6061-T6}
bodies:
  - name: grains
    phase: rigid
    material: iron
    shape: {union: [{circle: {center: [0.015, 0.02], radius: 0.004}}, {circle: {center: [0.035, 0.02], radius: 0.004}}]}
    clusters: per_part
    initial: {velocity: [0, -1], angular_velocity: 0}
  - name: target
    phase: solid
    material: al
    shape: {polygon: {vertices: [[0.005, 0.006], [0.045, 0.006], [0.045, 0.01], [0.005, 0.01]]}}
    hourglass: {xi: 1}
    erosion: failed
  - name: oil
    phase: fluid
    material: oil
    fill: rest
    shape: {box: {min: [0, 0.01], max: [0.05, 0.04]}}
surfaces:
  - {name: floor, segment: [[0, 0.005], [0.05, 0.005]], friction: 0.1}
contact: {law: hertz, distance: 1.0, damping: 0.1}
lubrication: {cutoff: 1.5, min_gap: 0.05}
end_time: 1.0e-7
probes:
  list:
    - {name: centre, type: rigid_centre, body: grains}
    - {name: floor_force, type: surface_force, surface: floor}
    - {name: profile_u, type: profile, field: velocity.x, body: oil, axis: y, bins: 10}
    - {name: hits, type: grain_impacts}
)yaml";

// 3D: a sphere, a hollow sphere and a cylinder of aluminium, a rigid plane and triangles.
inline const char* const kSolid3d = R"yaml(name: solid3d
dimension: 3
dp: 0.01
domain: {min: [0, 0, 0], max: [0.2, 0.2, 0.2]}
materials:
  al: {preset: Al6061-T6}
bodies:
  - name: ball
    phase: solid
    material: al
    shape: {sphere: {center: [0.1, 0.1, 0.1], radius: 0.04}}
    hourglass: {xi: 1}
    initial: {velocity: [0, -10, 0]}
  - name: shell
    phase: solid
    material: al
    shape: {hollow_sphere: {center: [0.1, 0.1, 0.1], inner: 0.06, outer: 0.08}}
  - name: rod
    phase: solid
    material: al
    shape: {cylinder: {start: [0.02, 0.02, 0.02], end: [0.02, 0.02, 0.18], radius: 0.01}}
surfaces:
  - {name: anvil, plane: {point: [0.1, 0.001, 0.1], normal: [0, 1, 0], size: [0.2, 0.2]}}
  - {name: wedge, triangles: [[[0.15, 0.001, 0.15], [0.19, 0.001, 0.15], [0.15, 0.001, 0.19]]]}
end_time: 1.0e-7
)yaml";

// One bad input: a base scene with `find` (which must occur once) replaced by `replace`; an
// empty `find` appends `replace`. `message` must appear in the one line of output.
struct SceneCase {
  const char* name;
  const char* base;
  const char* find;
  const char* replace;
  const char* message;
};

inline void PrintTo(const SceneCase& c, std::ostream* os) {
  *os << c.name;
}

inline std::string edited(const SceneCase& c) {
  std::string text = c.base;
  const std::string find = c.find;
  if (find.empty()) return text + c.replace;
  const auto at = text.find(find);
  if (at == std::string::npos || text.find(find, at + 1) != std::string::npos)
    ADD_FAILURE() << c.name << ": '" << find << "' must occur exactly once in the base scene";
  else
    text.replace(at, find.size(), c.replace);
  return text;
}

// Writes `text` to <out>/<name>.yaml and returns the path.
inline std::string write_scene(const std::string& out, const std::string& name,
                               const std::string& text) {
  std::filesystem::create_directories(out);
  const std::string path = out + "/" + name + ".yaml";
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// Runs monosph with a time limit (a hang fails the case) and checks what a bad input must give.
inline void expect_bad_input(const std::string& args, const std::string& message,
                             const std::string& out) {
  auto r = run_command("timeout -k 5 60 " + std::string(MONOSPH_BIN) + " " + args + " 2>&1");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find(message), std::string::npos) << "wanted: " << message << "\n" << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  EXPECT_EQ(r.output.find("\x1b["), std::string::npos) << "colour codes: " << r.output;
  const auto js = std::filesystem::path(out) / "summary.json";
  if (std::filesystem::exists(js)) {
    std::ifstream in(js);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(text.find("\"completed\""), std::string::npos) << text;
  }
}

inline void run_scene_case(const SceneCase& c) {
  const std::string out = out_dir("corpus_" + std::string(c.name));
  const std::string scene = write_scene(out, c.name, edited(c));
  expect_bad_input("run " + scene + " --threads 1 --quiet --out " + out + "/run", c.message,
                   out + "/run");
}

}  // namespace monosph::test
