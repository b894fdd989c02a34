#pragma once
// `mpirun -np N molsurf batch`: the batch's messages between the launched processes. The
// first process hands out the inputs one at a time to whichever process asks (it may run
// some itself) and gathers the results; the others ask when they have a free slot. Only
// the command's MPI files know how the messages travel; the batch sees bytes.
#include <memory>
#include <optional>
#include <string>

namespace molsurf::cli {

class WorkQueue {
 public:
  virtual ~WorkQueue() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;

  // Every process, once, before any work: the first process's error (empty: none), the
  // same on every process, so that all stop when the first cannot hand out work.
  virtual std::string start(const std::string& error) = 0;

  // Stops every process of the launch at once (MPI_Abort), after this one has said why:
  // the others would otherwise wait for its messages for ever.
  [[noreturn]] virtual void abort_all() = 0;

  // A process other than the first.
  virtual void ask() = 0;                                // for one more job
  virtual void send_result(const std::string& bytes) = 0;  // a finished job's row
  // The answer to the last ask, if it has come: a job's bytes, or empty when none is left.
  virtual std::optional<std::string> answer() = 0;

  // The first process.
  struct Message {
    int from = 0;
    bool asks = false;   // an ask; otherwise a result
    std::string result;  // a result's bytes
  };
  // The next message from any process, if one has come (messages from one process come
  // in the order it sent them).
  virtual std::optional<Message> receive() = 0;
  virtual void answer(int to, const std::string& job) = 0;  // empty: none left
};

// The queue of this MPI launch, when it has more than one process; null otherwise, and
// when molsurf was built without MPI.
std::unique_ptr<WorkQueue> join_work_queue();

}  // namespace molsurf::cli
