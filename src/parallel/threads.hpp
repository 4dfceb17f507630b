// How many OpenMP threads a run uses by default.
#pragma once

namespace monosph {

// CPUs this process may really use: the affinity mask (omp_get_num_procs) capped by a cgroup
// CPU quota (containers and CI runners often report the host's cores but grant two).
int usable_cpus();

// Default thread count: OMP_NUM_THREADS when set, otherwise usable_cpus(). More threads than
// CPUs make every parallel region wait on descheduled threads (measured: 14x slower).
void set_default_threads();

// Jobs and threads per job for `study` and `stability` (`verb`): never more threads in total
// than usable_cpus(). `jobs` is lowered to the CPUs and `threads` (0: CPUs / jobs) to CPUs / jobs,
// each with a one-line warning on stderr when the request is lowered.
struct JobThreads {
  int jobs, threads;
};
JobThreads jobs_and_threads(const char* verb, int jobs, int threads);

}  // namespace monosph
