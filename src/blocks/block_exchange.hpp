#pragma once
// What the blocks need from a message-passing layer, and nothing more: how many processes
// run the job, which one this is, each process's share of the structure sent by the first,
// the pieces' bytes gathered on the first, and the first's word sent to all. The block
// code is written against this; the MPI implementation lives in one file of the command
// (src/cli/mpi/mpi_exchange.cpp), so the library itself needs no MPI.
#include <string>
#include <vector>

namespace molsurf::blocks {

class BlockExchange {
 public:
  virtual ~BlockExchange() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  // Every process's bytes on rank 0, in rank order (empty elsewhere). Collective: every
  // process calls it once per exchange, even one that failed (it sends what went wrong).
  virtual std::vector<std::string> gather(const std::string& bytes) = 0;
  // Rank 0's `bytes` on every process (the others' argument is ignored). Collective.
  virtual std::string broadcast(const std::string& bytes) = 0;
  // From the first process to one other: send(to, bytes) on the first, receive() on `to`.
  virtual void send(int to, const std::string& bytes) = 0;
  virtual std::string receive() = 0;
};

}  // namespace molsurf::blocks
