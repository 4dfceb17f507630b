#pragma once
// Runs under mpirun and comparisons of their results with tolerances (MPI sums in another order).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "../validation/run_helpers.hpp"
#include "output/checkpoint.hpp"

namespace monosph::test {

inline Result mpirun(int ranks, const std::string& args) {
  // --oversubscribe: 3 ranks on this 2-core machine; --bind-to none: no core pinning.
  return run_command("timeout 300 " MONOSPH_MPIEXEC
                     " --allow-run-as-root --oversubscribe --bind-to none -x OMP_NUM_THREADS=1"
                     " -np " +
                     std::to_string(ranks) + " " + MONOSPH_BIN + " " + args + " 2>&1");
}

// The neighbour-list history (Simulation::save_state, restart.cpp): when a run last rebuilt its
// lists and how often, and the Eulerian solids' split F = F_ref F_init with the reference
// positions of that rebuild (MMB Eq. 30; F itself is compared). Ranks rebuild before every
// checkpoint, one rank does not: these differ.
inline bool rebuild_history(const std::string& name) {
  for (const char* h :
       {"build_position", "build_density", "reference_position", "incremental_deformation",
        "reference_deformation", "sim.builds", "sim.rebuild_requested"})
    if (name == h) return true;
  return name.rfind("sim.pending_removal.", 0) == 0;
}

// Every field of every particle (matched by id) within tol x the field's largest |value| (over
// all its components) + 1e-13: a field that is zero by symmetry holds round-off only. The
// rebuild history aside.
template <int D>
void expect_same_state(const std::string& a, const std::string& b, double tol = 1e-8) {
  Particles<D> pa, pb;
  auto ma = read_checkpoint<D>(a, pa);
  auto mb = read_checkpoint<D>(b, pb);
  EXPECT_DOUBLE_EQ(ma.time, mb.time);
  EXPECT_EQ(ma.step, mb.step);
  ASSERT_EQ(pa.size(), pb.size()) << "a different number of particles (removal differs)";
  std::map<std::int64_t, std::size_t> where;
  auto idb = pb.id();
  for (std::size_t i = 0; i < pb.size(); ++i) where[idb[i]] = i;
  auto ida = pa.id();
  std::vector<std::size_t> map(pa.size());
  for (std::size_t i = 0; i < pa.size(); ++i) {
    auto it = where.find(ida[i]);
    ASSERT_NE(it, where.end()) << "particle id " << ida[i] << " only in " << a;
    map[i] = it->second;
  }
  double worst_rel = 0;  // largest difference / field scale, fields not zero by symmetry
  for (const auto& f : pa.fields()) {
    if (rebuild_history(f.name)) continue;
    const auto& g = pb.field(f.name);
    const int nc = f.ncomp;
    if (f.type == FieldType::Int) {
      for (std::size_t i = 0; i < pa.size(); ++i)
        for (int c = 0; c < nc; ++c)
          ASSERT_EQ(f.ints[i * nc + c], g.ints[map[i] * nc + c]) << f.name << " of id " << ida[i];
      continue;
    }
    double scale = 0, diff = 0;
    std::int64_t worst = -1;
    for (std::size_t i = 0; i < pa.size(); ++i)
      for (int c = 0; c < nc; ++c) {
        const double x = f.real[i * nc + c], y = g.real[map[i] * nc + c];
        scale = std::max(scale, std::abs(x));
        if (!(std::abs(x - y) <= diff)) diff = std::abs(x - y), worst = ida[i];
      }
    if (scale > 1e-10) worst_rel = std::max(worst_rel, diff / scale);
    EXPECT_LE(diff, tol * scale + 1e-13)
        << f.name << ": largest difference " << diff << " (field scale " << scale
        << ") at particle id " << worst;
  }
  std::printf("  %zu particles, largest field difference %.2e of the field's scale\n", pa.size(),
              worst_rel);
  auto count = [](const std::map<std::string, double>& s) {
    return std::count_if(s.begin(), s.end(),
                         [](const auto& kv) { return !rebuild_history(kv.first); });
  };
  EXPECT_EQ(count(ma.scalars), count(mb.scalars));
  for (const auto& [k, v] : ma.scalars) {
    if (rebuild_history(k)) continue;
    auto it = mb.scalars.find(k);
    ASSERT_NE(it, mb.scalars.end()) << k;
    EXPECT_NEAR(it->second, v, tol * std::max(1.0, std::abs(v))) << k;
  }
}

// The probe series of two runs: the same rows (steps), every value within 1e-8 of its column's
// scale (its largest |value| over the run and over the other components of the same vector
// probe, name_x, name_y...) + 1e-13.
inline void expect_same_probes(const std::string& a, const std::string& b) {
  auto ts = read_csv(a), tm = read_csv(b);
  ASSERT_EQ(ts.head, tm.head);
  ASSERT_EQ(ts.cols[0].size(), tm.cols[0].size());
  EXPECT_EQ(ts.cols[1], tm.cols[1]) << "steps";
  auto stem = [](const std::string& h) {
    const auto n = h.size();
    return n > 2 && h[n - 2] == '_' && std::string("xyz").find(h[n - 1]) != std::string::npos
               ? h.substr(0, n - 2)
               : h;
  };
  for (std::size_t k = 2; k < ts.head.size(); ++k) {
    double scale = 0;
    for (std::size_t l = 2; l < ts.head.size(); ++l)
      if (stem(ts.head[l]) == stem(ts.head[k]))
        for (double v : ts.cols[l]) scale = std::max(scale, std::abs(v));
    for (std::size_t q = 0; q < ts.cols[k].size(); ++q)
      EXPECT_NEAR(tm.cols[k][q], ts.cols[k][q], 1e-8 * scale + 1e-13)
          << ts.head[k] << " at t = " << ts.cols[0][q];
  }
}

}  // namespace monosph::test
