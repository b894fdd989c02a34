#pragma once
// The command under a message-passing launcher (mpirun, srun): the one place that knows
// MPI. The library's blocks talk to it only through blocks::BlockExchange.
#include <memory>

#include "blocks/block_exchange.hpp"

namespace molsurf::cli {

// MPI started for this process when a launcher started it (its environment says so:
// OMPI_COMM_WORLD_SIZE, PMI_SIZE or PMIX_RANK), and finalized when the object goes; null
// otherwise, or when molsurf was built without MPI (MOLSURF_MPI off or not found).
std::unique_ptr<blocks::BlockExchange> start_message_passing(int& argc, char**& argv);

}  // namespace molsurf::cli
