#include "heat/heat_module.hpp"

#include <algorithm>
#include <limits>

#include "core/initial_temperature.hpp"

namespace monosph {

template <int D>
HeatModule<D>::HeatModule(Simulation<D>& sim) {
  // Explicit diffusion is stable for dt below about 0.25 rho c h^2 / k; 0.1 leaves a margin.
  const double h = sim.kernel().h();
  for (const auto& b : sim.bodies()) {
    k_.push_back(module_params<HeatBodyKeys>(b.params).conductivity);
    const Material& mat = sim.materials()[b.material];
    if (k_.back() > 0)
      max_dt_ = std::min(max_dt_, 0.1 * mat.density * mat.heat_capacity * h * h / k_.back());
  }
  auto& p = sim.particles();
  kT_ = p.add_field("temperature", 1, FieldType::Real, true);  // the solid module's, if it has it
  kdT_ = p.add_field("conduction_rate", 1, FieldType::Real, true);  // dT/dt by conduction, K/s
  p.set_meaning({kT_, kdT_}, phase_bit(kSolid) | phase_bit(kFluid));
}

template <int D>
bool HeatModule<D>::needed(const Simulation<D>& sim) {
  return std::any_of(sim.bodies().begin(), sim.bodies().end(), [](const BodyInfo& b) {
    return module_params<HeatBodyKeys>(b.params).conductivity > 0;
  });
}

// The initial temperature (Material::initial_temperature, as the solid module sets it).
template <int D>
void HeatModule<D>::on_create(Simulation<D>& sim) {
  set_initial_temperatures(sim, kT_);
}

// Cleary & Monaghan 1999 (J. Comput. Phys. 148:227): c_i dT_i/dt = sum_j 4 m_j / (rho_i rho_j)
// k_i k_j / (k_i + k_j) (T_i - T_j) r_ij . grad_i W_ij / (r_ij^2 + eta^2): antisymmetric in i, j,
// so that sum m c T is conserved; the harmonic mean k_ij gives the flux across a change of k.
template <int D>
void HeatModule<D>::rates(Simulation<D>& sim) {
  auto& p = sim.particles();
  sim.exchange({kT_});  // the neighbours' temperatures on the ghosts
  const auto& pl = sim.pairs();
  auto T = p.template view<double>(kT_);
  auto dT = p.template view<double>(kdT_);
  auto m = p.m();
  auto x = p.x();
  auto rho = p.rho();
  auto bd = p.body();
  auto mt = p.material();
  const double h = sim.kernel().h(), eta2 = 0.01 * h * h;
  const std::size_t n = p.size();
#pragma omp parallel for schedule(runtime)
  for (std::size_t i = 0; i < n; ++i) {
    const double ki = k_[bd[i]];
    double rate = 0;
    for (std::size_t k = pl.begin(i); ki > 0 && k < pl.end(i); ++k) {
      const int j = pl.j[k];
      const double kj = k_[bd[j]];
      if (!(kj > 0)) continue;
      const double r2 = pl.r(x, i, k).squaredNorm();
      rate +=
          4 * m[j] / rho[j] * (ki * kj / (ki + kj)) * (T[i] - T[j]) * pl.f[k] * r2 / (r2 + eta2);
    }
    dT[i] = ki > 0 ? rate / (rho[i] * sim.materials()[mt[i]].heat_capacity) : 0.0;
  }
}

template <int D>
void HeatModule<D>::drift(Simulation<D>& sim, double dt) {
  auto& p = sim.particles();
  auto T = p.template view<double>(kT_);
  auto dT = p.template view<double>(kdT_);
  const std::size_t n = p.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) T[i] += dt * dT[i];
}

template <int D>
double HeatModule<D>::max_dt(Simulation<D>&) {
  return max_dt_;
}

template class HeatModule<2>;
template class HeatModule<3>;

}  // namespace monosph
