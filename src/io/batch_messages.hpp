#pragma once
// The batch's messages between processes (`mpirun molsurf batch`): a job handed out by the
// first process, and its result sent back, as bytes. Every field is kept as it is (a file
// name or an error message may hold any byte, tabs and line breaks included), so a row that
// crossed processes is the row the first process would have made itself.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "io/batch_manifest.hpp"

namespace molsurf::io {

// One structure to run: its place in the input list, its path, its result's name.
struct BatchJob {
  std::size_t index = 0;
  std::string input;
  std::string name;
};

std::string batch_job_bytes(const BatchJob& job);
// nullopt for bytes that no batch_job_bytes made.
std::optional<BatchJob> batch_job_from_bytes(std::string_view bytes);

// A finished job: its index and row.
std::string batch_result_bytes(std::size_t index, const BatchRow& row);
std::optional<std::pair<std::size_t, BatchRow>> batch_result_from_bytes(std::string_view bytes);

}  // namespace molsurf::io
