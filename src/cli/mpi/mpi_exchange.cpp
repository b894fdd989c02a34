// The blocks' exchange over MPI (Open MPI from Debian): every MPI call of molsurf is here.
#include <mpi.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/mpi/message_passing.hpp"

namespace molsurf::cli {

namespace {

// Messages travel in parts of at most 1 GiB: MPI counts are ints.
constexpr std::size_t kPart = std::size_t{1} << 30;

void check(int code, const char* what) {
  if (code != MPI_SUCCESS) throw std::runtime_error(std::string("MPI: ") + what + " failed");
}

class MpiExchange final : public blocks::BlockExchange {
 public:
  MpiExchange(int& argc, char**& argv) {
    int provided = 0;
    // Only the main thread calls MPI; OpenMP threads compute between the calls.
    check(MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
  ~MpiExchange() override { MPI_Finalize(); }
  MpiExchange(const MpiExchange&) = delete;
  MpiExchange& operator=(const MpiExchange&) = delete;

  int rank() const override { return rank_; }
  int size() const override { return size_; }

  std::vector<std::string> gather(const std::string& bytes) override {
    std::vector<std::string> all;
    if (rank_ != 0) {
      send_bytes(0, bytes);
      return all;
    }
    all.resize(static_cast<std::size_t>(size_));
    all[0] = bytes;
    for (int r = 1; r < size_; ++r) all[static_cast<std::size_t>(r)] = receive_bytes(r);
    return all;
  }

  void send(int to, const std::string& bytes) override { send_bytes(to, bytes); }
  std::string receive() override { return receive_bytes(0); }

  std::string broadcast(const std::string& bytes) override {
    std::uint64_t n = bytes.size();
    check(MPI_Bcast(&n, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD), "MPI_Bcast");
    std::string out = rank_ == 0 ? bytes : std::string(n, '\0');
    for (std::size_t at = 0; at < n; at += kPart)
      check(MPI_Bcast(out.data() + at, static_cast<int>(std::min<std::size_t>(kPart, n - at)), MPI_BYTE, 0,
                      MPI_COMM_WORLD),
            "MPI_Bcast");
    return out;
  }

 private:
  void send_bytes(int to, const std::string& bytes) {
    const std::uint64_t n = bytes.size();
    check(MPI_Send(&n, 1, MPI_UINT64_T, to, 0, MPI_COMM_WORLD), "MPI_Send");
    for (std::size_t at = 0; at < bytes.size(); at += kPart)
      check(MPI_Send(bytes.data() + at, static_cast<int>(std::min(kPart, bytes.size() - at)), MPI_BYTE, to, 1,
                     MPI_COMM_WORLD),
            "MPI_Send");
  }

  std::string receive_bytes(int from) {
    std::uint64_t n = 0;
    check(MPI_Recv(&n, 1, MPI_UINT64_T, from, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE), "MPI_Recv");
    std::string in(n, '\0');
    for (std::size_t at = 0; at < n; at += kPart)
      check(MPI_Recv(in.data() + at, static_cast<int>(std::min<std::size_t>(kPart, n - at)), MPI_BYTE, from, 1,
                     MPI_COMM_WORLD, MPI_STATUS_IGNORE),
            "MPI_Recv");
    return in;
  }

  int rank_ = 0, size_ = 1;
};

bool launched_by_mpi() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(name) != nullptr) return true;
  return false;
}

}  // namespace

std::unique_ptr<blocks::BlockExchange> start_message_passing(int& argc, char**& argv) {
  if (!launched_by_mpi()) return nullptr;
  return std::make_unique<MpiExchange>(argc, argv);
}

}  // namespace molsurf::cli
