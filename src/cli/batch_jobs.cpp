#include "cli/batch_jobs.hpp"

#include <fcntl.h>
#include <sched.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstring>
#include <fstream>
#include <sstream>
#include <thread>

#include "molsurf/error.hpp"
#include "molsurf/io.hpp"

extern char** environ;

namespace molsurf::cli {

namespace {

// The variables by which a launcher tells a process it belongs to the launch
// (main.cpp starts MPI when it sees one).
bool is_launch_variable(const char* entry) {
  for (const char* prefix : {"OMPI_", "PMIX_", "PMI_"})
    if (std::strncmp(entry, prefix, std::strlen(prefix)) == 0) return true;
  return false;
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

}  // namespace

int available_cores() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) == 0 && CPU_COUNT(&set) > 0) return CPU_COUNT(&set);
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

BatchJobs::BatchJobs(BatchJobOptions options)
    : options_(std::move(options)), temporaries_(options_.output_directory) {
  std::error_code error;
  self_ = std::filesystem::read_symlink("/proc/self/exe", error).string();
  if (error) throw Error("cannot find the molsurf executable (/proc/self/exe): " + error.message());
  for (char** entry = environ; *entry != nullptr; ++entry)
    if (!is_launch_variable(*entry)) environment_.emplace_back(*entry);
}

BatchJobs::~BatchJobs() {
  for (const auto& [pid, job] : running_) {
    kill(pid, SIGKILL);
    int status = 0;
    waitpid(pid, &status, 0);
  }
}

void BatchJobs::start(const io::BatchJob& job) {
  const std::filesystem::path base = options_.output_directory / job.name;
  std::vector<std::string> args{self_, job.input, "-q", "--threads", "1", "--json", base.string() + ".json",
                                "--stale-temporaries-removed"};
  temporaries_.remove_stale_of(job.name + ".json");
  if (options_.mesh.empty()) {
    args.push_back("--areas-only");
  } else {
    args.insert(args.end(), {"-o", base.string() + "." + options_.mesh});
    for (const std::filesystem::path& file : mesh_output_files(base.string() + "." + options_.mesh))
      temporaries_.remove_stale_of(file.filename().string());
  }
  args.insert(args.end(), options_.options.begin(), options_.options.end());
  std::vector<char*> argv, envp;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  for (std::string& e : environment_) envp.push_back(e.data());
  envp.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  const std::string log = (options_.output_directory / "logs" / (job.name + ".log")).string();
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = -1;
  const int failed = posix_spawn(&pid, self_.c_str(), &actions, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  if (failed != 0) {
    io::BatchRow row;
    row.status = "failed";
    row.message = "cannot start a job: " + std::string(std::strerror(failed));
    not_started_.emplace_back(job.index, row);
    return;
  }
  running_[pid] = {job, std::chrono::steady_clock::now()};
}

std::vector<std::pair<std::size_t, io::BatchRow>> BatchJobs::finished() {
  std::vector<std::pair<std::size_t, io::BatchRow>> done = std::move(not_started_);
  not_started_.clear();
  // Each job waited for by its own id: a library of this process (MPI's) may have children too.
  for (auto it = running_.begin(); it != running_.end();) {
    int status = 0;
    if (waitpid(it->first, &status, WNOHANG) == it->first) {
      done.emplace_back(it->second.job.index, outcome(it->second, status));
      it = running_.erase(it);
    } else {
      ++it;
    }
  }
  const auto now = std::chrono::steady_clock::now();
  for (auto& [pid, job] : running_)
    if (options_.timeout > 0 && !job.timed_out &&
        std::chrono::duration<double>(now - job.start).count() > options_.timeout) {
      kill(pid, SIGKILL);
      job.timed_out = true;
    }
  return done;
}

io::BatchRow BatchJobs::outcome(const Running& job, int status) const {
  namespace fs = std::filesystem;
  io::BatchRow row;
  row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - job.start).count();
  const fs::path base = options_.output_directory / job.job.name;
  const fs::path log = options_.output_directory / "logs" / (job.job.name + ".log");
  std::ifstream report_file(base.string() + ".json");
  std::stringstream report;
  report << report_file.rdbuf();
  const std::optional<double> area = io::report_number(report.str(), "area");
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && area) {
    row.status = "ok";
    row.area = *area;
    row.volume = io::report_number(report.str(), "volume").value_or(0);
    row.atoms = static_cast<std::int64_t>(io::report_number(report.str(), "atoms").value_or(-1));
    row.cavities = static_cast<std::int64_t>(io::report_number(report.str(), "cavities").value_or(-1));
    std::error_code ignored;
    fs::remove(log, ignored);
  } else {
    row.status = "failed";
    row.message = job.timed_out ? "stopped after the --timeout of " + std::to_string(options_.timeout) + " s"
                                : failure_message(log, status);
  }
  return row;
}

}  // namespace molsurf::cli
