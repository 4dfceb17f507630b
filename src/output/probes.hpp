#pragma once
// Probes: scalar time series sampled from the particles (CSV), and the metrics a scene's
// reference values are compared with (frequency, period, final, max, min, mean).
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/simulation.hpp"
#include "output/profile_probe.hpp"

namespace monosph {

template <int D>
class Probes {
 public:
  explicit Probes(Simulation<D>& sim);  // validates field names (InputError)
  ~Probes();
  const std::vector<std::string>& columns() const { return columns_; }
  // One value per column; profile probes (no column) sample their bins and write their files.
  std::vector<double> sample(Simulation<D>& sim);
  // Profile probes write profile_<name>.csv into `dir` from now on (rank 0); on a restart
  // (`restarted`) the rows of an existing file up to `time` are kept. Without this call they
  // sample but write nothing (tests).
  void open_profiles(const std::filesystem::path& dir, bool restarted, double time);
  // The first failed write of a profile file ("output: cannot write FILE: ..."), "" if none.
  std::string write_error() {
    for (auto& pr : profiles_)
      if (auto e = pr->write_error(); !e.empty()) return e;
    return "";
  }
  // The last sample of the profile probe `name` (std::out_of_range when there is none).
  const ProfileBins& profile(const std::string& name) const;
  // Checkpoint state: the particle id each `tracked` probe follows (probes.<k>.tracked_id, k its
  // index in the list), so that a restart follows the same particles.
  void save_state(std::map<std::string, double>& s) const;
  void load_state(const std::map<std::string, double>& s);

 private:
  struct Item;
  std::vector<std::unique_ptr<Item>> items_;
  std::vector<std::unique_ptr<ProfileProbe<D>>> profiles_;
  std::vector<std::string> columns_;
};

// Sizes (particle counts, largest first) of the connected pieces of a point set: two points
// are linked when closer than `link`. xyz holds dim coordinates per point.
std::vector<long> piece_sizes(const std::vector<double>& xyz, int dim, double link);

// Evaluates a reference measure on the series (t, y) restricted to t >= start.
// Returns NaN when the series cannot give it (e.g. fewer than two zero crossings), and then the
// reason in *why.
double measure_series(const std::string& measure, const std::vector<double>& t,
                      const std::vector<double>& y, double start, std::string* why = nullptr);

}  // namespace monosph
