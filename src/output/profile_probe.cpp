#include "output/profile_probe.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "output/atomic_file.hpp"
#include "output/probe_csv.hpp"

namespace monosph {

namespace {

// Smallest and largest projection on `axis` of the corners of the box [lo, hi].
template <int D>
void project_box(const Point& lo, const Point& hi, const Vec<D>& axis, double& a, double& b) {
  a = std::numeric_limits<double>::infinity(), b = -a;
  for (int corner = 0; corner < (1 << D); ++corner) {
    double s = 0;
    for (int k = 0; k < D; ++k) s += axis[k] * ((corner >> k) & 1 ? hi[k] : lo[k]);
    a = std::min(a, s), b = std::max(b, s);
  }
}

}  // namespace

template <int D>
ProfileProbe<D>::ProfileProbe(const Simulation<D>& sim, const ProbeSpec& spec, int field, int body)
    : spec_(spec), field_(field), body_(body) {
  const Scene& scene = sim.scene();
  for (int a = 0; a < D; ++a) axis_[a] = spec.axis[a];
  if (spec.range.size() == 2) {
    lo_ = spec.range[0], hi_ = spec.range[1];
  } else if (body >= 0) {
    Point lo, hi;
    scene.bodies[body].shape.bounds(lo, hi);
    project_box<D>(lo, hi, axis_, lo_, hi_);
  } else {
    project_box<D>(scene.domain_min, scene.domain_max, axis_, lo_, hi_);
  }
  for (int a = 0; a < D; ++a)
    if (axis_[a] == 1 && scene.periodic[a])
      wrap_ = a, wrap_lo_ = scene.domain_min[a], wrap_len_ = scene.domain_max[a] - wrap_lo_;
  const int n = spec.bins;
  bins_.position.resize(n);
  for (int k = 0; k < n; ++k) bins_.position[k] = lo_ + (k + 0.5) * (hi_ - lo_) / n;
  bins_.mean.assign(n, std::numeric_limits<double>::quiet_NaN());
  bins_.particles.assign(n, 0);
}

template <int D>
double ProfileProbe<D>::along(const Vec<D>& x) const {
  if (wrap_ >= 0) {  // between neighbour rebuilds a particle may sit just outside the box
    const double c = x[wrap_];
    return c - wrap_len_ * std::floor((c - wrap_lo_) / wrap_len_);
  }
  return axis_.dot(x);
}

template <int D>
const ProfileBins& ProfileProbe<D>::sample(Simulation<D>& sim) {
  auto& p = sim.particles();
  auto x = p.x();
  auto m = p.m();
  auto rho = p.rho();
  auto bd = p.body();
  const Field& f = p.field(field_);
  const int nc = f.ncomp, c = nc > 1 ? spec_.component : 0;
  const int n = spec_.bins;
  sums_.assign(3 * n, 0.0);
  for (std::size_t i = 0; i < sim.owned(); ++i) {  // serial: the same for any thread count
    if (body_ >= 0 && bd[i] != body_) continue;
    const double s = along(x[i]);
    if (!(s >= lo_ && s <= hi_)) continue;
    const int k = std::min(n - 1, static_cast<int>((s - lo_) / (hi_ - lo_) * n));
    const double v = m[i] / rho[i];
    const double value =
        f.type == FieldType::Real ? f.real[i * nc + c] : static_cast<double>(f.ints[i * nc + c]);
    sums_[3 * k] += v * value, sums_[3 * k + 1] += v, sums_[3 * k + 2] += 1;
  }
  sim.comm().sum(std::span<double>(sums_));
  for (int k = 0; k < n; ++k) {
    bins_.particles[k] = std::lround(sums_[3 * k + 2]);
    bins_.mean[k] = bins_.particles[k] > 0 ? sums_[3 * k] / sums_[3 * k + 1]
                                           : std::numeric_limits<double>::quiet_NaN();
  }
  if (out_.is_open()) write(sim.time(), sim.step());
  return bins_;
}

template <int D>
void ProfileProbe<D>::open(const std::filesystem::path& dir, bool restarted, double time) {
  if (!Comm::world().root()) return;
  path_ = dir / ("profile_" + spec_.name + ".csv");
  const std::string header = "time,step,position,mean,particles";
  std::error_code ec;
  if (restarted && std::filesystem::exists(path_, ec)) {
    // The complete rows up to the restart time (not a partly written last one), kept in place.
    std::ifstream in(path_, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    long kept = 0;
    const std::size_t keep =
        probe_csv_prefix(text.str(), header, 5, -1, time, path_.string(), kept);
    std::filesystem::resize_file(path_, keep, ec);
    if (ec) throw InputError("output: cannot write " + path_.string() + ": " + ec.message());
    out_.open(path_, std::ios::app);
  } else {
    out_.open(path_);
    out_ << header << "\n";
  }
  if (!out_.is_open()) throw InputError("output: cannot write " + path_.string());
  out_.flush();  // a failed write is reported by write_error(), on every rank at once
}

template <int D>
std::string ProfileProbe<D>::write_error() {
  if (!out_.is_open()) return "";
  try {
    check_stream(out_, path_);
  } catch (const OutputError& e) {
    return e.what();
  }
  return "";
}

template <int D>
void ProfileProbe<D>::write(double time, long step) {
  for (std::size_t k = 0; k < bins_.mean.size(); ++k) {
    const double mean = bins_.mean[k];
    out_ << fmt::format("{:.17g},{},{:.17g},{},{}\n", time, step, bins_.position[k],
                        std::isnan(mean) ? std::string("nan") : fmt::format("{:.17g}", mean),
                        bins_.particles[k]);
  }
  out_.flush();  // a user can follow the profile during the run
}

template class ProfileProbe<2>;
template class ProfileProbe<3>;

}  // namespace monosph
