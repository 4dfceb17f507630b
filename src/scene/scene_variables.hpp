#pragma once
// The scene's `variables`: named numbers every expression of the scene can use, e.g.
//   variables: {angle: 30, speed: 100}
//   initial: {velocity: ["speed*cos(angle*pi/180)", "-speed*sin(angle*pi/180)"]}
// `--set variables.angle=45` and `study --vary variables.angle=15,30` change them; a --set of a
// variable the scene does not declare is an error (a typo would otherwise change nothing).
#include <string>
#include <vector>

#include "scene/expression.hpp"
#include "scene/scene_reader.hpp"

namespace monosph {

// Reads the optional `variables` map of the scene root (names: identifiers that are not x, y, z,
// t, pi, e, uniform or a muparser function; values: numbers, not expressions).
Constants read_variables(MapReader& root);

// Throws InputError if `item` ("variables.NAME=value") names a variable that `root` (the scene
// before any override) does not declare.
void check_variable_override(const YAML::Node& root, const std::string& item);

}  // namespace monosph
