#pragma once
// The jobs of `molsurf batch` that run on this machine: each structure is this program on
// one thread, in its own process, so that a crash, a signal or a --timeout fails that
// structure alone. The process's own MPI variables are left out of the jobs' environment:
// a job is a plain run, never a member of the launch.
#include <sys/types.h>

#include <chrono>
#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "io/batch_manifest.hpp"
#include "io/batch_messages.hpp"
#include "io/temporary_name.hpp"

namespace molsurf::cli {

struct BatchJobOptions {
  std::filesystem::path output_directory;
  std::string mesh;                  // a format to write, or empty: --areas-only
  std::vector<std::string> options;  // passed to every job
  double timeout = 0;                // seconds; 0: none
};

class BatchJobs {
 public:
  explicit BatchJobs(BatchJobOptions options);
  BatchJobs(const BatchJobs&) = delete;
  BatchJobs& operator=(const BatchJobs&) = delete;
  // Jobs still running are stopped (SIGKILL) and waited for.
  ~BatchJobs();

  // Starts the job; a job that cannot start is a failed result at the next finished().
  void start(const io::BatchJob& job);
  std::size_t running() const { return running_.size(); }
  // The jobs that ended since the last call, each with its index and its row's status,
  // numbers (from its JSON report), message and seconds; stops those past the timeout.
  std::vector<std::pair<std::size_t, io::BatchRow>> finished();

 private:
  struct Running {
    io::BatchJob job;
    std::chrono::steady_clock::time_point start;
    bool timed_out = false;
  };
  io::BatchRow outcome(const Running& job, int status) const;

  BatchJobOptions options_;
  // The output folder's possible temporaries, listed once: each job's are removed as it
  // starts, and the job lists nothing (a sweep's folder of 200 000 reports takes 40 ms to
  // list, more than a small structure's whole run).
  detail::TemporaryListing temporaries_;
  std::string self_;                  // this executable
  std::vector<std::string> environment_;  // ours without the launcher's MPI variables
  std::map<pid_t, Running> running_;
  std::vector<std::pair<std::size_t, io::BatchRow>> not_started_;
};

// The cores this process may run on (its affinity: under mpirun, the cores bound to it).
int available_cores();

}  // namespace molsurf::cli
