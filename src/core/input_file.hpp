#pragma once
// Files a run reads (the scene, STL meshes, checkpoints, suite files): regular files of a bounded
// size only. A device (/dev/zero), a FIFO or a socket would block or never end; each is bad input.
#include <cstdint>
#include <string>

namespace monosph {

// Largest scene or suite text (a scene is a few kB; meshes belong in STL files).
inline constexpr std::uintmax_t kMaxSceneBytes = 64ull << 20;  // 64 MiB
// Largest STL file (50 bytes a binary triangle: 43 million triangles).
inline constexpr std::uintmax_t kMaxStlBytes = 2ull << 30;  // 2 GiB

// Throws InputError "<cannot> (<why>)" unless `file` is a readable regular file of at most
// max_bytes (0: any size); `cannot` names the key or file, e.g. "x.yaml: cannot read scene file".
void check_input_file(const std::string& file, const std::string& cannot,
                      std::uintmax_t max_bytes = 0);

// The whole content of a checked input file.
std::string read_input_file(const std::string& file, const std::string& cannot,
                            std::uintmax_t max_bytes);

}  // namespace monosph
