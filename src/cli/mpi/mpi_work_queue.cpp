// The batch's work queue over MPI: small messages on a communicator of its own (a copy of
// MPI_COMM_WORLD, so that they never meet the blocks'), polled without blocking, because
// the first process also waits on its own jobs while it hands out work.
#include <mpi.h>

#include <cstdlib>
#include <stdexcept>
#include <string>

#include "cli/mpi/work_queue.hpp"

namespace molsurf::cli {

namespace {

constexpr int kToFirst = 1;   // asks and results, to the first process
constexpr int kToWorker = 2;  // answers to an ask
constexpr char kAsk = 'A', kResult = 'R';

void check(int code, const char* what) {
  if (code != MPI_SUCCESS) throw std::runtime_error(std::string("MPI: ") + what + " failed");
}

class MpiWorkQueue final : public WorkQueue {
 public:
  MpiWorkQueue() {
    check(MPI_Comm_dup(MPI_COMM_WORLD, &comm_), "MPI_Comm_dup");
    MPI_Comm_rank(comm_, &rank_);
    MPI_Comm_size(comm_, &size_);
  }
  ~MpiWorkQueue() override { MPI_Comm_free(&comm_); }
  MpiWorkQueue(const MpiWorkQueue&) = delete;
  MpiWorkQueue& operator=(const MpiWorkQueue&) = delete;

  int rank() const override { return rank_; }
  int size() const override { return size_; }

  std::string start(const std::string& error) override {
    std::string text = rank_ == 0 ? error : std::string();
    int length = static_cast<int>(text.size());
    check(MPI_Bcast(&length, 1, MPI_INT, 0, comm_), "MPI_Bcast");
    text.resize(static_cast<std::size_t>(length));
    if (length > 0) check(MPI_Bcast(text.data(), length, MPI_CHAR, 0, comm_), "MPI_Bcast");
    return text;
  }

  [[noreturn]] void abort_all() override {
    MPI_Abort(MPI_COMM_WORLD, 1);
    std::abort();  // MPI_Abort does not return
  }

  void ask() override { send(std::string(1, kAsk), 0, kToFirst); }
  void send_result(const std::string& bytes) override { send(kResult + bytes, 0, kToFirst); }
  std::optional<std::string> answer() override {
    return poll(0, kToWorker, nullptr);
  }

  std::optional<Message> receive() override {
    int from = 0;
    std::optional<std::string> bytes = poll(MPI_ANY_SOURCE, kToFirst, &from);
    if (!bytes) return std::nullopt;
    if (bytes->empty() || ((*bytes)[0] != kAsk && (*bytes)[0] != kResult))
      throw std::runtime_error("MPI: a batch message of unknown kind from process " + std::to_string(from));
    Message message;
    message.from = from;
    message.asks = (*bytes)[0] == kAsk;
    if (!message.asks) message.result = bytes->substr(1);
    return message;
  }
  void answer(int to, const std::string& job) override { send(job, to, kToWorker); }

 private:
  // A message is one file name and one row: far below MPI's int count.
  void send(const std::string& bytes, int to, int tag) {
    check(MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, to, tag, comm_), "MPI_Send");
  }
  std::optional<std::string> poll(int from, int tag, int* source) {
    int arrived = 0;
    MPI_Status status;
    check(MPI_Iprobe(from, tag, comm_, &arrived, &status), "MPI_Iprobe");
    if (!arrived) return std::nullopt;
    int count = 0;
    check(MPI_Get_count(&status, MPI_BYTE, &count), "MPI_Get_count");
    std::string bytes(static_cast<std::size_t>(count), '\0');
    check(MPI_Recv(bytes.data(), count, MPI_BYTE, status.MPI_SOURCE, tag, comm_, MPI_STATUS_IGNORE), "MPI_Recv");
    if (source != nullptr) *source = status.MPI_SOURCE;
    return bytes;
  }

  MPI_Comm comm_ = MPI_COMM_NULL;
  int rank_ = 0, size_ = 1;
};

}  // namespace

std::unique_ptr<WorkQueue> join_work_queue() {
  int initialized = 0, finalized = 0;
  MPI_Initialized(&initialized);
  MPI_Finalized(&finalized);
  if (!initialized || finalized) return nullptr;
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (size < 2) return nullptr;
  return std::make_unique<MpiWorkQueue>();
}

}  // namespace molsurf::cli
