#pragma once
// The pressure equation of the decomposed fluid as one system over the ranks: each rank's owned
// particles are numbered after those of the ranks before it, and the halo copies carry their
// owners' numbers, so that a rank's rows can name any column of the whole system
// (GlobalNumbering, sph/linear_solver.hpp).
#include <mpi.h>

#include "linear_solver.hpp"
#include "particle_exchange.hpp"

namespace isph {

// Collective over comm; `plan` as add_halo made it.
GlobalNumbering number_globally(MPI_Comm comm, const HaloPlan& plan);

}  // namespace isph
