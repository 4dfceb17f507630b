#pragma once
// Heat conduction in solid and fluid bodies (`heat_conduction: {conductivity: k}`): the SPH
// conduction term of Cleary & Monaghan 1999 on the `temperature` field, which the solid module's
// adiabatic heating (MMB Eq. 24) and Johnson-Cook softening share.
#include <limits>
#include <vector>

#include "core/simulation.hpp"
#include "heat/heat_keys.hpp"

namespace monosph {

template <int D>
class HeatModule : public Module<D> {
 public:
  explicit HeatModule(Simulation<D>& sim);
  std::string name() const override { return "heat"; }
  void on_create(Simulation<D>& sim) override;
  void rates(Simulation<D>& sim) override;
  void drift(Simulation<D>& sim, double dt) override;
  double max_dt(Simulation<D>& sim) override;

  // Whether any body of the scene conducts heat (the module is then needed).
  static bool needed(const Simulation<D>& sim);

 private:
  std::vector<double> k_;                                    // conductivity per body (0: none)
  double max_dt_ = std::numeric_limits<double>::infinity();  // diffusion limit (constant)
  int kT_ = -1, kdT_ = -1;                                   // temperature, its conduction rate
};

}  // namespace monosph
