// How many OpenMP threads a run uses by default.
#pragma once

namespace monosph {

// CPUs this process may really use: the affinity mask (omp_get_num_procs) capped by a cgroup
// CPU quota (containers and CI runners often report the host's cores but grant two).
int usable_cpus();

// Default thread count: OMP_NUM_THREADS when set, otherwise usable_cpus(). More threads than
// CPUs make every parallel region wait on descheduled threads (measured: 14x slower).
void set_default_threads();

}  // namespace monosph
