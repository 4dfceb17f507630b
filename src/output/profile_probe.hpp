#pragma once
// Profile probe (`type: profile`): the volume-weighted mean sum V_i f_i / sum V_i (V = m/rho) of
// a field component in `bins` equal bins along `axis`, and the particle count of each bin, at
// every probe sample. Written in long format to profile_<name>.csv in the output folder:
// time,step,position,mean,particles (position: the bin centre along the axis; mean "nan" for
// a bin without particles). Default range: the bounding box of the body's shape projected on the
// axis (its extent at t = 0), or the domain's without a body. MPI: sums per bin over the owned
// particles, then over the ranks; rank 0 writes.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/simulation.hpp"

namespace monosph {

struct ProfileBins {
  std::vector<double> position, mean;  // bin centres; NaN mean in an empty bin
  std::vector<long> particles;
};

template <int D>
class ProfileProbe {
 public:
  // `field` and `body` (-1: every body) are indices into the particle fields and bodies.
  ProfileProbe(const Simulation<D>& sim, const ProbeSpec& spec, int field, int body);
  const std::string& name() const { return spec_.name; }
  double lower() const { return lo_; }
  double upper() const { return hi_; }
  // The means and counts now (collective under MPI); appended to the file when one is open.
  const ProfileBins& sample(Simulation<D>& sim);
  const ProfileBins& last() const { return bins_; }
  // Opens dir/profile_<name>.csv (rank 0 only; the others do nothing): a new file with its
  // header, or on a restart the existing file's rows with time <= `time` kept. InputError when it
  // cannot be created.
  void open(const std::filesystem::path& dir, bool restarted, double time);
  // "output: cannot write FILE: reason" once a write to the open file has failed, else "".
  std::string write_error();

 private:
  double along(const Vec<D>& x) const;  // position along the axis (periodic axes wrapped)
  void write(double time, long step);

  ProbeSpec spec_;
  int field_, body_;
  Vec<D> axis_;
  double lo_ = 0, hi_ = 1;
  int wrap_ = -1;  // the axis is this periodic coordinate axis
  double wrap_lo_ = 0, wrap_len_ = 0;
  ProfileBins bins_;
  std::vector<double> sums_;  // per bin: sum V f, sum V, count
  std::ofstream out_;
  std::filesystem::path path_;
};

}  // namespace monosph
