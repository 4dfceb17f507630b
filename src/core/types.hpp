#pragma once
// Basic numeric types shared by every module.
#include <Eigen/Dense>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace monosph {

template <int D>
using Vec = Eigen::Matrix<double, D, 1, Eigen::DontAlign>;
template <int D>
using Mat = Eigen::Matrix<double, D, D, Eigen::DontAlign>;
using Mat3 = Eigen::Matrix<double, 3, 3, Eigen::DontAlign>;
using Vec3 = Eigen::Matrix<double, 3, 1, Eigen::DontAlign>;

// Phase of a particle: which kind of matter it is.
enum Phase : std::int64_t { kFluid = 0, kSolid = 1, kRigid = 2, kWall = 3 };
// A set of phases as a bit mask (Field::phases).
constexpr unsigned phase_bit(Phase p) {
  return 1u << static_cast<unsigned>(p);
}

// An error in user input (scene, command line): reported in one line, exit code 2.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A run that cannot go on (NaN, collapsed step...): last state written, exit code 3.
struct RunAborted : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Output that could not be written during a run (disk full, I/O error): one line naming the
// file, exit code 6. (An output folder that cannot be written at the start is an InputError.)
struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Pads a D-vector to 3 components (for output).
template <int D>
inline Vec3 pad3(const Vec<D>& v) {
  Vec3 r = Vec3::Zero();
  r.template head<D>() = v;
  return r;
}

}  // namespace monosph
