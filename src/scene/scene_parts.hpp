#pragma once
// The readers of the scene's sections (scene.cpp puts them together). Each throws InputError
// with a one-line message naming the key path.
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "scene/scene_reader.hpp"

namespace monosph {

// scene_yaml.cpp: the YAML text, checked as a tree (every key a plain, unique name; every
// scalar valid UTF-8), and the command line's --set overrides.
void apply_override(YAML::Node& root, const std::string& item);

// scene_materials.cpp: one entry of `materials`.
Material read_material(const std::string& name, const YAML::Node& n, const std::string& path,
                       const Constants* constants);

// scene_shapes.cpp: a body's or region's shape.
Shape read_shape(const YAML::Node& node, const std::string& path, int dim,
                 const Constants* constants);

// scene_bodies.cpp: `bodies` (with the modules they switch on) and `boundary_conditions`.
void read_bodies(MapReader& root, Scene& s);
void read_boundaries(MapReader& root, Scene& s);
// A list of `dim` expressions at key, each checked (in the variables of "xyzt" given).
std::vector<std::string> expressions(MapReader& r, const std::string& key, int dim,
                                     const Constants& vars, const std::string& variables = "xyzt");

// scene_surfaces.cpp: `surfaces`.
void read_surfaces(MapReader& root, Scene& s, YAML::Node& tree, const std::string& origin);

// scene_sections.cpp: `time_step`, `guards`, `output`, `reference`, `checks`, `limits`.
void read_time_step(MapReader& root, Scene& s);
void read_guards(MapReader& root, Scene& s);
void read_output(MapReader& root, Scene& s);
void read_references(MapReader& root, Scene& s);
void read_checks(MapReader& root, Scene& s);
void read_limits(MapReader& root, Scene& s);

// scene_checks.cpp: checks of the whole scene once read: expressions that evaluate to a
// non-finite value, the `name` as a file name, the size guard.
void check_name(const std::string& name);
// Control characters, or bidirectional controls (U+202A-U+202E, U+2066-U+2069: a file name with
// one displays reversed); printable() writes them as \xNN / \uNNNN (one line, in order).
bool has_controls(const std::string& text);
std::string printable(const std::string& text);
void check_scene_expressions(const Scene& s);
void check_size(const Scene& s);

}  // namespace monosph
