#pragma once
// What a checkpoint holds is checked before a run uses it: a forged or damaged file stops with
// one line naming the file, the field and the particle (exit code 2), never a crash or a run
// that goes on from bad data.
#include <filesystem>
#include <string>
#include <vector>

#include "output/checkpoint.hpp"
#include "scene/scene.hpp"

namespace monosph {

// Checks that need no scene: every real value finite, time/dt/step/next_id in range, module
// scalars finite, ids in [0, next_id) and distinct. Returns the problem ("" if none).
std::string check_checkpoint_data(const std::vector<Field>& fields, const CheckpointMeta& meta);

// Index fields against the scene the checkpoint holds: phase, material, body, boundary, cluster
// (with the clusters.count of the module state), and positions within the domain. Throws
// InputError("checkpoint FILE: ...").
template <int D>
void check_checkpoint_indices(const std::filesystem::path& file, const Particles<D>& p,
                              const CheckpointMeta& meta, const Scene& scene);

}  // namespace monosph
