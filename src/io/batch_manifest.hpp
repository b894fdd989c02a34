#pragma once
// What `molsurf batch` knows about each input across runs: the manifest in the output
// directory (one tab-separated line per finished job, appended as jobs finish, the last
// line of an input winning), from which a rerun skips finished work and the summary tables
// are written. The command (src/cli/batch_command.cpp) runs the jobs; what they mean is here.
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace molsurf::io {

struct BatchRow {
  std::string input;    // the input's path as given (list line or directory entry)
  std::string hash;     // of the input's bytes and the job's options (hex)
  std::string status;   // "ok" or "failed"
  double seconds = 0;   // the job's wall time
  std::int64_t atoms = -1, cavities = -1;  // -1: unknown (a failed job)
  double area = 0, volume = 0;
  std::string message;  // a failed job's error
};

// The structure files to run: the lines of a list file (blank lines and '#' comments
// skipped; relative paths from the list's directory), or a directory's structure files
// (.pdb .ent .cif .mmcif .pqr .xyzr, gzipped or not) in name order, recursively.
std::vector<std::filesystem::path> batch_inputs(const std::filesystem::path& list_or_directory);

// The result's name for each input: its file name without the structure extensions, made
// unique in input order (1abc, 1abc-2, ...).
std::vector<std::string> batch_result_names(const std::vector<std::filesystem::path>& inputs);

// FNV-1a (64 bits) of the file's bytes and then of `options`, as 16 hex digits: a rerun
// with the same input and options finds the same hash.
std::string batch_hash(const std::filesystem::path& file, const std::string& options);

// Each input's last row in the manifest (none if it does not exist).
std::map<std::string, BatchRow> read_batch_manifest(const std::filesystem::path& manifest);
// One manifest line (tab-separated; tabs and newlines in the message become spaces).
std::string batch_manifest_line(const BatchRow& row);

// A sweep's rows, one per input in input order, and the inputs still to run: an input
// whose bytes and options hash as in the manifest's row is taken from the manifest (a
// failed one only without `retry_failed`).
struct BatchResume {
  std::vector<BatchRow> rows;
  std::vector<std::size_t> pending;  // indices into rows, in input order
};
BatchResume resume_batch(const std::vector<std::filesystem::path>& inputs, const std::string& job_options,
                         const std::map<std::string, BatchRow>& manifest, bool retry_failed);

// A finished job's outcome (status, numbers, message, seconds) put into `row`, whose input
// and hash stay.
void record_batch_result(BatchRow& row, const BatchRow& result);

// The summary: CSV (RFC 4180 quoting) and JSON lines, one row per input in input order.
std::string batch_summary_csv(const std::vector<BatchRow>& rows);
std::string batch_summary_jsonl(const std::vector<BatchRow>& rows);

// The first `"key": value` number in a molsurf JSON report (the top level's, for the keys
// written before any nested list: input.atoms, area, volume, cavities); nullopt if absent.
std::optional<double> report_number(const std::string& json, const std::string& key);

}  // namespace molsurf::io
