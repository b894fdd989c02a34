// molsurf built without MPI: `mpirun molsurf batch` starts processes that each run the
// whole sweep alone.
#include "cli/mpi/work_queue.hpp"

namespace molsurf::cli {

std::unique_ptr<WorkQueue> join_work_queue() { return nullptr; }

}  // namespace molsurf::cli
