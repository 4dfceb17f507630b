#pragma once
// Probes: scalar time series sampled from the particles (CSV), and the metrics a scene's
// reference values are compared with (frequency, period, final, max, min, mean).
#include <memory>
#include <string>
#include <vector>

#include "simulation.hpp"

namespace monosph {

template <int D>
class Probes {
 public:
  explicit Probes(Simulation<D>& sim);  // validates field names (InputError)
  ~Probes();
  const std::vector<std::string>& columns() const { return columns_; }
  std::vector<double> sample(Simulation<D>& sim);

 private:
  struct Item;
  std::vector<std::unique_ptr<Item>> items_;
  std::vector<std::string> columns_;
};

// Sizes (particle counts, largest first) of the connected pieces of a point set: two points
// are linked when closer than `link`. xyz holds dim coordinates per point.
std::vector<long> piece_sizes(const std::vector<double>& xyz, int dim, double link);

// Evaluates a reference measure on the series (t, y) restricted to t >= start.
// Returns NaN when the series cannot give it (e.g. fewer than two zero crossings).
double measure_series(const std::string& measure, const std::vector<double>& t,
                      const std::vector<double>& y, double start);

}  // namespace monosph
