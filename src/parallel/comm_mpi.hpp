#pragma once
// The MPI communicator of a Comm, for the files that call MPI themselves (comm.hpp, which
// almost every file includes, leaves <mpi.h> out).
#include <mpi.h>

#include "parallel/comm.hpp"

namespace monosph {

// MPI_COMM_WORLD when the process was started by mpirun, MPI_COMM_NULL otherwise (every Comm
// is the world: there are no sub-communicators).
MPI_Comm mpi_comm(const Comm& c);

}  // namespace monosph
