#pragma once
// Work that only the first process of an exchange can do (read the structure, check its
// spheres, cut it into blocks), with its verdict sent to every process: what it threw is
// thrown on every other process too, as FirstProcessVerdict, so that none waits for a share
// that will not come. The first process prints the message; the others stop without a word,
// so that mpirun's output holds it once (as under molsurf batch).
#include <exception>
#include <string>

#include "blocks/block_exchange.hpp"
#include "molsurf/error.hpp"
#include "molsurf/parameters.hpp"

namespace molsurf::blocks {

// The first process's verdict as another process throws it: the first prints it.
class FirstProcessVerdict : public Error {
 public:
  using Error::Error;
};

// `work()` on the first process (or on a process alone: then only that). Collective when
// `exchange` has several processes: the others wait for the verdict and throw it as
// FirstProcessVerdict.
template <class Work>
void on_first_process(BlockExchange* exchange, Work&& work) {
  if (exchange == nullptr || exchange->size() <= 1) {
    work();
    return;
  }
  // The verdict: empty when the work succeeded; "P" parameter "\n" problem; "E" message.
  if (exchange->rank() == 0) {
    try {
      work();
    } catch (const ParameterError& e) {
      exchange->broadcast("P" + e.parameter() + "\n" + e.problem());
      throw;
    } catch (const std::exception& e) {
      exchange->broadcast(std::string("E") + e.what());
      throw;
    }
    exchange->broadcast({});
    return;
  }
  const std::string verdict = exchange->broadcast({});
  if (verdict.empty()) return;
  if (verdict[0] == 'P') {
    const std::size_t split = verdict.find('\n');
    throw FirstProcessVerdict(verdict.substr(1, split - 1) + ": " + verdict.substr(split + 1));
  }
  throw FirstProcessVerdict(verdict.substr(1));
}

}  // namespace molsurf::blocks
