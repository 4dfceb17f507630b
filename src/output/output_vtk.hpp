#pragma once
// VtkSeries<D>: a time series of particle frames for ParaView. Each frame is one binary,
// zlib-compressed .vtu (vertex cells); DIR/basename.pvd lists every frame written so far.
#include <filesystem>
#include <string>
#include <vector>

#include "core/particles.hpp"

namespace monosph {

template <int D>
class VtkSeries {
 public:
  // Creates dir if needed; throws InputError("output: cannot write to DIR: reason") if it is not
  // a writable directory.
  VtkSeries(std::filesystem::path dir, std::string basename);

  // Writes DIR/basename_SSSSSS.vtu (S = step, 6 digits at least) with every output field plus
  // extra_fields (unknown name -> InputError), then rewrites the .pvd. Returns the .vtu path.
  // D-vectors become 3-component arrays and DxD (or 3x3) tensors 9-component row-major arrays,
  // padded with zeros in 2D. The new frame replaces .pvd entries for the same file (same step)
  // or with a time >= its own, so the list stays ordered after a restart.
  std::filesystem::path write(const Particles<D>& p, double time, long step,
                              const std::vector<std::string>& extra_fields = {});
  // Under MPI: each rank writes its first `owned` particles as basename_SSSSSS_pR.vtu, rank 0 a
  // basename_SSSSSS.pvtu that lists the pieces, and the .pvd lists the .pvtu files.
  void set_piece(int rank, int ranks) { rank_ = rank, ranks_ = ranks; }
  std::filesystem::path write(const Particles<D>& p, std::size_t owned, double time, long step,
                              const std::vector<std::string>& extra_fields = {});

  // For a restart: reads the existing .pvd (if any), keeps its entries with time <= restart_time
  // (a frame written at the checkpoint time is not written again), drops later ones and rewrites
  // the .pvd; later frames are appended. Returns how many frames were kept.
  int restore_frames(double restart_time);

  std::filesystem::path pvd_path() const { return dir_ / (basename_ + ".pvd"); }
  const std::filesystem::path& dir() const { return dir_; }
  int frames() const { return static_cast<int>(frames_.size()); }

 private:
  struct Frame {
    double time;
    std::string file;  // relative to dir_
  };
  void write_pvd() const;

  std::filesystem::path dir_;
  std::string basename_;
  std::vector<Frame> frames_;
  int rank_ = 0, ranks_ = 1;
};

extern template class VtkSeries<2>;
extern template class VtkSeries<3>;

}  // namespace monosph
