#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <thread>

#include "cli/batch_manifest.hpp"
#include "cli/commands.hpp"
#include "cli/validators.hpp"
#include "molsurf/error.hpp"
#include "molsurf/output_files.hpp"

extern char** environ;

namespace molsurf::cli {

namespace {

// The sweep's own options (the command line's only).
constexpr WholeParameter kJobsParameter{"jobs", 0, 4096};
constexpr NumberParameter kTimeoutParameter{"timeout", 0, 1e9, true};  // seconds

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
  app.add_option("-j,--jobs", jobs, "Structures run at a time, each on one thread (default: one per core)")
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

// The result's name for each input: its file name without the structure extensions, made
// unique in input order (1abc, 1abc-2, ...).
std::vector<std::string> result_names(const std::vector<std::filesystem::path>& inputs) {
  std::vector<std::string> names;
  std::map<std::string, int> seen;
  for (const std::filesystem::path& p : inputs) {
    std::filesystem::path stem = p.filename();
    while (stem.has_extension()) stem = stem.stem();
    const int n = ++seen[stem.string()];
    names.push_back(n == 1 ? stem.string() : stem.string() + "-" + std::to_string(n));
  }
  return names;
}

// The error a failed job printed last ("molsurf: error: ..."), or how it ended.
std::string failure_message(const std::filesystem::path& log, int status) {
  std::ifstream in(log);
  std::string last;
  for (std::string line; std::getline(in, line);)
    if (line.rfind("molsurf: error: ", 0) == 0) last = line.substr(16);
    else if (line.rfind("molsurf: internal error: ", 0) == 0) last = line.substr(9);
  if (WIFSIGNALED(status)) return "stopped by signal " + std::to_string(WTERMSIG(status)) + (last.empty() ? "" : ": " + last);
  if (!last.empty()) return last;
  return "exit status " + std::to_string(WEXITSTATUS(status));
}

struct Running {
  std::size_t index;
  std::chrono::steady_clock::time_point start;
  bool timed_out = false;
};

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

}  // namespace

int BatchCommand::run() const {
  namespace fs = std::filesystem;
  const std::vector<fs::path> inputs = batch_inputs(input);
  const std::vector<std::string> names = result_names(inputs);
  std::error_code error;
  fs::create_directories(output_directory / "logs", error);
  if (error) throw Error(output_directory.string() + ": cannot make the folder: " + error.message());
  std::string job_options = mesh;
  for (const std::string& o : options) job_options += " " + o;
  const fs::path manifest_path = output_directory / "manifest.tsv";
  std::map<std::string, BatchRow> previous = read_batch_manifest(manifest_path);
  std::ofstream manifest(manifest_path, std::ios::app);
  if (!manifest) throw Error(manifest_path.string() + ": cannot write");

  std::vector<BatchRow> rows(inputs.size());
  std::vector<std::size_t> pending;
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    rows[k].input = inputs[k].string();
    rows[k].hash = batch_hash(inputs[k], job_options);
    const auto found = previous.find(rows[k].input);
    if (found != previous.end() && found->second.hash == rows[k].hash &&
        (found->second.status == "ok" || !retry_failed)) {
      rows[k] = found->second;  // finished before, with the same input and options
      continue;
    }
    pending.push_back(k);
  }
  const std::size_t skipped = inputs.size() - pending.size();
  const int width = jobs > 0 ? jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  if (!quiet)
    std::cerr << "molsurf batch: " << inputs.size() << " structures, " << skipped << " done before, " << pending.size()
              << " to run, " << width << " at a time -> " << output_directory.string() << "\n";

  // Each job is this program on one structure and one thread.
  const std::string self = fs::read_symlink("/proc/self/exe", error).string();
  if (error) throw Error("cannot find the molsurf executable (/proc/self/exe): " + error.message());
  const auto start_job = [&](std::size_t k) -> pid_t {
    const fs::path base = output_directory / names[k];
    std::vector<std::string> args{self, inputs[k].string(), "-q", "--threads", "1", "--json", base.string() + ".json"};
    if (mesh.empty()) args.push_back("--areas-only");
    else args.insert(args.end(), {"-o", base.string() + "." + mesh});
    args.insert(args.end(), options.begin(), options.end());
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    const std::string log = (output_directory / "logs" / (names[k] + ".log")).string();
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    pid_t pid = -1;
    const int failed = posix_spawn(&pid, self.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (failed != 0) throw Error("cannot start a job: " + std::string(std::strerror(failed)));
    return pid;
  };

  const auto batch_start = std::chrono::steady_clock::now();
  ProgressLine line(!quiet && (progress || isatty(STDERR_FILENO)), pending.size());
  std::map<pid_t, Running> running;
  std::size_t next = 0, done = 0, failures = 0;
  while (next < pending.size() || !running.empty()) {
    while (next < pending.size() && running.size() < static_cast<std::size_t>(width)) {
      const std::size_t k = pending[next++];
      running[start_job(k)] = {k, std::chrono::steady_clock::now()};
    }
    int status = 0;
    const pid_t pid = waitpid(-1, &status, WNOHANG);
    const auto now = std::chrono::steady_clock::now();
    if (pid <= 0) {
      for (auto& [child, job] : running)
        if (timeout > 0 && !job.timed_out && std::chrono::duration<double>(now - job.start).count() > timeout) {
          kill(child, SIGKILL);
          job.timed_out = true;
        }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      line.draw(done, failures, running.size(), std::chrono::duration<double>(now - batch_start).count());
      continue;
    }
    const auto it = running.find(pid);
    if (it == running.end()) continue;
    const Running job = it->second;
    running.erase(it);
    BatchRow& row = rows[job.index];
    row.seconds = std::chrono::duration<double>(now - job.start).count();
    const fs::path base = output_directory / names[job.index];
    const fs::path log = output_directory / "logs" / (names[job.index] + ".log");
    std::ifstream report_file(base.string() + ".json");
    std::stringstream report;
    report << report_file.rdbuf();
    const std::optional<double> area = report_number(report.str(), "area");
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && area) {
      row.status = "ok";
      row.message.clear();
      row.area = *area;
      row.volume = report_number(report.str(), "volume").value_or(0);
      row.atoms = static_cast<std::int64_t>(report_number(report.str(), "atoms").value_or(-1));
      row.cavities = static_cast<std::int64_t>(report_number(report.str(), "cavities").value_or(-1));
      fs::remove(log, error);
    } else {
      row.status = "failed";
      row.message = job.timed_out ? "stopped after the --timeout of " + std::to_string(timeout) + " s"
                                  : failure_message(log, status);
      ++failures;
    }
    manifest << batch_manifest_line(row) << std::flush;  // a rerun after a crash resumes from here
    ++done;
    line.draw(done, failures, running.size(), std::chrono::duration<double>(now - batch_start).count());
  }
  std::error_code ignored;
  fs::remove(output_directory / "logs", ignored);  // only when empty

  OutputFiles files;
  files.add_text(output_directory / "summary.csv", batch_summary_csv(rows));
  files.add_text(output_directory / "summary.jsonl", batch_summary_jsonl(rows));
  files.commit();
  std::size_t failed_total = 0;
  for (const BatchRow& r : rows) failed_total += r.status != "ok";
  if (!quiet) {
    std::cerr << "molsurf batch: " << done << " run (" << failures << " failed), " << skipped << " done before; "
              << failed_total << " of " << rows.size() << " failed in all: " << (output_directory / "summary.csv").string()
              << "\n";
  }
  return failed_total == 0 ? 0 : 1;
}

}  // namespace molsurf::cli
