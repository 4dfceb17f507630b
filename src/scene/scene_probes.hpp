#pragma once
// The scene section `probes` (read after bodies, boundary conditions and surfaces, which probes
// name) and the probe columns that references and checks may name.
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "scene/scene_reader.hpp"

namespace monosph {

// Reads `every` and `list` of the section into s.probe_every and s.probes (InputError naming the
// key path, e.g. "probes.list[2].body: ...").
void read_probes(MapReader& section, Scene& s);

// A reference or check names a probe column of probes.csv: a scalar probe, or one component of a
// vector probe ("load_y"). Profile probes write their own file and have no column.
bool names_probe_column(const std::vector<ProbeSpec>& probes, const std::string& name);

}  // namespace monosph
