#pragma once
// How many threads a run may use. OpenMP starts its team when a parallel region first
// asks for it, and libgomp ends the process when it cannot (a limit on virtual memory,
// processes or a container's pids), with no word from molsurf: a thread count is therefore
// capped, before any work, at what this process can start at once. The command line
// (--threads) and Python (threads=) both ask here.
#include <string>

namespace molsurf {

struct ThreadCount {
  int threads = 0;   // the count to use (0 stays 0: OpenMP's default, all cores)
  std::string note;  // why `requested` was lowered; empty when it was not
};

// `requested` when this process can start that many threads at once (each with OpenMP's
// stack: OMP_STACKSIZE, or the default thread stack), else half the number it could start
// (the limit that stopped them binds the work's memory too), with a note. Counts up to the cores are taken as they are; above them the threads are
// started (and ended) to find out, which costs some 30 microseconds each.
ThreadCount startable_threads(int requested);

}  // namespace molsurf
