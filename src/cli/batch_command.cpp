#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <exception>
#include <fstream>
#include <functional>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <thread>

#include "cli/batch_jobs.hpp"
#include "cli/commands.hpp"
#include "cli/mpi/work_queue.hpp"
#include "cli/validators.hpp"
#include "io/batch_manifest.hpp"
#include "io/batch_messages.hpp"
#include "molsurf/error.hpp"
#include "molsurf/output_files.hpp"

namespace molsurf::cli {

namespace {

// The sweep's own options (the command line's only).
constexpr WholeParameter kJobsParameter{"jobs", 0, 4096};
constexpr NumberParameter kTimeoutParameter{"timeout", 0, 1e9, true};  // seconds
// How long a loop with nothing to do sleeps before it looks at its jobs and messages again.
constexpr auto kPollInterval = std::chrono::milliseconds(20);

}  // namespace

void BatchCommand::add_options(CLI::App& app) {
  app.add_option("INPUT", input,
                 "A list of structure files (one path per line, '#' comments; relative to the list's folder)\n"
                 "or a folder, whose structure files are run in name order, subfolders included")
      ->required();
  app.add_option("-o,--output", output_directory,
                 "Folder for the results (made if missing): NAME.json per structure, NAME.EXT with --mesh,\n"
                 "summary.csv and summary.jsonl (file, atoms, area, volume, cavities, seconds, status,\n"
                 "message), manifest.tsv (what is done, for reruns), logs/NAME.log for failures")
      ->required();
  app.add_option("-j,--jobs", jobs,
                 "Structures run at a time (per process under mpirun), each on one thread\n"
                 "(default: one per core this process may use)")
      ->check(whole_number_in(kJobsParameter));
  app.add_option("--mesh", mesh,
                 "Also write each structure's surface in this format (vtp, vtk, ply, off, stl, obj, vert, msh);\n"
                 "default: the exact areas and volumes only (--areas-only)")
      ->check(CLI::IsMember({"vtp", "vtk", "ply", "off", "stl", "obj", "vert", "msh"}));
  app.add_option("--timeout", timeout, "Seconds one structure may take before it is stopped and counted failed")
      ->check(number_in(kTimeoutParameter));
  app.add_flag("--retry-failed", retry_failed,
               "Run again the structures that failed before (a rerun skips finished ones, failed or not)");
  app.add_flag("--progress", progress, "Show the progress line even when stderr is not a terminal");
  app.add_flag("-q,--quiet", quiet, "Print nothing but errors");
  app.add_option("OPTIONS", options,
                 "molsurf options for every structure, after --: molsurf batch pdb/ -o out -- --probe 1.2");
}

namespace {

class ProgressLine {
 public:
  ProgressLine(bool enabled, std::size_t total) : enabled_(enabled), total_(total) {}
  ~ProgressLine() {
    if (drawn_) std::fputc('\n', stderr);
  }
  void draw(std::size_t done, std::size_t failed, std::size_t running, double seconds) {
    if (!enabled_) return;
    const double rate = seconds > 0 ? done / seconds : 0;
    const double left = rate > 0 ? (total_ - done) / rate : 0;
    std::fprintf(stderr, "\r[%zu/%zu] %zu failed, %zu running, %.1f s, %.2f per s, about %.0f s left   ", done, total_,
                 failed, running, seconds, rate, left);
    std::fflush(stderr);
    drawn_ = true;
  }

 private:
  bool enabled_, drawn_ = false;
  std::size_t total_;
};

// A process of an MPI launch other than the first: runs the jobs it is handed, `width` at
// a time, and sends back each one's row.
void run_handed_jobs(WorkQueue& queue, BatchJobs& jobs, std::size_t width) {
  bool asked = false, none_left = false;
  while (!none_left || jobs.running() > 0) {
    bool busy = false;
    if (!none_left && !asked && jobs.running() < width) {
      queue.ask();
      asked = true;
    }
    if (asked)
      if (const std::optional<std::string> answer = queue.answer()) {
        asked = false;
        busy = true;
        if (answer->empty()) {
          none_left = true;
        } else {
          const std::optional<io::BatchJob> job = io::batch_job_from_bytes(*answer);
          if (!job) throw std::runtime_error("a job from the first process that cannot be read");
          jobs.start(*job);
        }
      }
    for (const auto& [index, row] : jobs.finished()) {
      queue.send_result(io::batch_result_bytes(index, row));
      busy = true;
    }
    if (!busy) std::this_thread::sleep_for(kPollInterval);
  }
}

// The first process (or the only one): runs `jobs` here, `width` at a time, and hands
// them out to the other processes as they ask, until every job's row has come to `record`
// and every other process has been told that none is left. `draw` shows the progress
// (the jobs running anywhere).
void run_and_hand_out(const std::vector<io::BatchJob>& jobs, BatchJobs& local, std::size_t width, WorkQueue* queue,
                      const std::function<void(std::size_t, const io::BatchRow&)>& record,
                      const std::function<void(std::size_t)>& draw) {
  const int others = queue ? queue->size() - 1 : 0;
  std::size_t next = 0;
  std::size_t handed_out = 0;  // jobs running on the other processes
  int released = 0;            // processes told that none is left
  while (next < jobs.size() || local.running() > 0 || handed_out > 0 || released < others) {
    bool busy = false;
    while (next < jobs.size() && local.running() < width) {
      local.start(jobs[next++]);
      busy = true;
    }
    while (queue) {
      const std::optional<WorkQueue::Message> message = queue->receive();
      if (!message) break;
      busy = true;
      if (message->asks && next < jobs.size()) {
        queue->answer(message->from, io::batch_job_bytes(jobs[next++]));
        ++handed_out;
      } else if (message->asks) {
        queue->answer(message->from, "");
        ++released;
      } else {
        const auto result = io::batch_result_from_bytes(message->result);
        if (!result || handed_out == 0)
          throw std::runtime_error("a result from process " + std::to_string(message->from) + " that cannot be read");
        --handed_out;
        record(result->first, result->second);
      }
    }
    for (const auto& [k, result] : local.finished()) {
      record(k, result);
      busy = true;
    }
    if (!busy) std::this_thread::sleep_for(kPollInterval);
    draw(local.running() + handed_out);
  }
}

}  // namespace

int BatchCommand::run() const {
  const std::unique_ptr<WorkQueue> queue = join_work_queue();
  BatchJobOptions job_options{output_directory, mesh, options, timeout};
  const std::size_t width = static_cast<std::size_t>(jobs > 0 ? jobs : available_cores());
  if (queue && queue->rank() != 0) {
    // The first process says whether the sweep goes ahead (and, if not, why).
    if (!queue->start("").empty()) return 1;
    try {
      BatchJobs handed(job_options);
      run_handed_jobs(*queue, handed, width);
    } catch (const std::exception& e) {
      std::cerr << "molsurf: error: batch, process " << queue->rank() << ": " << e.what() << "\n";
      queue->abort_all();
    }
    return 0;
  }

  namespace fs = std::filesystem;
  std::vector<fs::path> inputs;
  std::vector<std::string> names;
  io::BatchResume resume;
  std::ofstream manifest;
  const fs::path manifest_path = output_directory / "manifest.tsv";
  try {
    inputs = io::batch_inputs(input);
    names = io::batch_result_names(inputs);
    std::error_code error;
    fs::create_directories(output_directory / "logs", error);
    if (error) throw Error(output_directory.string() + ": cannot make the folder: " + error.message());
    std::string hashed_options = mesh;
    for (const std::string& o : options) hashed_options += " " + o;
    resume = io::resume_batch(inputs, hashed_options, io::read_batch_manifest(manifest_path), retry_failed);
    manifest.open(manifest_path, std::ios::app);
    if (!manifest) throw Error(manifest_path.string() + ": cannot write");
  } catch (const std::exception& e) {
    if (queue) queue->start(e.what());
    throw;
  }
  if (queue) queue->start("");
  std::vector<io::BatchRow>& rows = resume.rows;
  const std::vector<std::size_t>& pending = resume.pending;
  const std::size_t skipped = inputs.size() - pending.size();
  const int processes = queue ? queue->size() : 1;
  if (!quiet)
    std::cerr << "molsurf batch: " << inputs.size() << " structures, " << skipped << " done before, " << pending.size()
              << " to run, " << width << " at a time"
              << (processes > 1 ? " on each of " + std::to_string(processes) + " processes" : "") << " -> "
              << output_directory.string() << "\n";

  const auto batch_start = std::chrono::steady_clock::now();
  ProgressLine line(!quiet && (progress || isatty(STDERR_FILENO)), pending.size());
  std::size_t done = 0, failures = 0;
  std::vector<io::BatchJob> to_run;
  for (const std::size_t k : pending) to_run.push_back({k, inputs[k].string(), names[k]});
  const auto record = [&](std::size_t k, const io::BatchRow& result) {
    if (k >= rows.size())
      throw std::runtime_error("a result for input " + std::to_string(k) + " of " + std::to_string(rows.size()));
    io::record_batch_result(rows[k], result);
    manifest << io::batch_manifest_line(rows[k]) << std::flush;  // a rerun after a crash resumes from here
    ++done;
    failures += result.status != "ok";
  };
  const auto draw = [&](std::size_t running) {
    line.draw(done, failures, running,
              std::chrono::duration<double>(std::chrono::steady_clock::now() - batch_start).count());
  };
  try {
    BatchJobs local(job_options);
    run_and_hand_out(to_run, local, width, queue.get(), record, draw);
  } catch (const std::exception& e) {
    if (!queue) throw;
    std::cerr << "molsurf: error: batch: " << e.what() << "\n";
    queue->abort_all();
  }
  std::error_code ignored;
  fs::remove(output_directory / "logs", ignored);  // only when empty

  OutputFiles files;
  files.add_text(output_directory / "summary.csv", io::batch_summary_csv(rows));
  files.add_text(output_directory / "summary.jsonl", io::batch_summary_jsonl(rows));
  files.commit();
  std::size_t failed_total = 0;
  for (const io::BatchRow& r : rows) failed_total += r.status != "ok";
  if (!quiet) {
    std::cerr << "molsurf batch: " << done << " run (" << failures << " failed), " << skipped << " done before; "
              << failed_total << " of " << rows.size() << " failed in all: " << (output_directory / "summary.csv").string()
              << "\n";
  }
  return failed_total == 0 ? 0 : 1;
}

}  // namespace molsurf::cli
