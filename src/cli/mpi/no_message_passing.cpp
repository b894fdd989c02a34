// molsurf built without MPI: a launcher's processes each run the whole job alone.
#include "cli/mpi/message_passing.hpp"

namespace molsurf::cli {

std::unique_ptr<blocks::BlockExchange> start_message_passing(int&, char**&) { return nullptr; }

}  // namespace molsurf::cli
