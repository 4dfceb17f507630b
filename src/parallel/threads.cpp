#include "parallel/threads.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>

namespace monosph {
namespace {

// CPU quota in CPUs from cgroup v2 (cpu.max: "quota period" or "max period") or v1
// (cpu.cfs_quota_us / cpu.cfs_period_us); 0 when there is none.
double cgroup_quota() {
  std::ifstream v2("/sys/fs/cgroup/cpu.max");
  std::string quota;
  double period = 0;
  if (v2 >> quota >> period && quota != "max" && period > 0) return std::stod(quota) / period;
  std::ifstream q("/sys/fs/cgroup/cpu/cpu.cfs_quota_us"), p("/sys/fs/cgroup/cpu/cpu.cfs_period_us");
  double qv = -1, pv = 0;
  if (q >> qv && p >> pv && qv > 0 && pv > 0) return qv / pv;
  return 0;
}

}  // namespace

int usable_cpus() {
  int n = omp_get_num_procs();
  try {
    const double quota = cgroup_quota();
    if (quota > 0) n = std::min(n, std::max(1, static_cast<int>(std::ceil(quota - 1e-9))));
  } catch (...) {  // unreadable quota: keep the affinity count
  }
  return std::max(1, n);
}

void set_default_threads() {
  const char* env = std::getenv("OMP_NUM_THREADS");
  if (env && *env) return;
  // Under mpirun the ranks on one machine share its cores: more threads than cores make
  // OpenMP's spinning threads run 10-50x slower.
  int local = 1;
  for (const char* v : {"OMPI_COMM_WORLD_LOCAL_SIZE", "MPI_LOCALNRANKS"})
    if (const char* s = std::getenv(v)) local = std::max(local, std::atoi(s));
  omp_set_num_threads(std::max(1, usable_cpus() / local));
}

JobThreads jobs_and_threads(const char* verb, int jobs, int threads) {
  const int cpus = usable_cpus();
  JobThreads r{std::clamp(jobs, 1, cpus), 0};
  if (r.jobs < jobs)
    fmt::print(stderr, "monosph: warning: {}: --jobs {} lowered to {} (the usable CPUs)\n", verb,
               jobs, r.jobs);
  const int most = std::max(1, cpus / r.jobs);
  r.threads = threads > 0 ? std::min(threads, most) : most;
  if (threads > most)
    fmt::print(stderr,
               "monosph: warning: {}: --threads {} lowered to {} ({} jobs on {} usable CPUs)\n",
               verb, threads, most, r.jobs, cpus);
  return r;
}

}  // namespace monosph
