#pragma once
// Runs the molsurf executable as a user would and captures what it prints.
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <stdexcept>
#include <sstream>
#include <string>
#include <vector>

namespace molsurf::testing {

struct CommandResult {
  int exit_code = -1;
  std::string out, err;
};

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The lines of `text`, without their newlines.
inline std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// `arguments` is appended to the executable's path as is (quote paths yourself);
// `shell_prefix` runs before it in the same shell (e.g. "ulimit -v 500000; ");
// `stdout_redirection` replaces the capture of standard output (e.g. "> /dev/full", ">&-").
inline CommandResult run_molsurf(const std::string& arguments, const std::filesystem::path& workdir,
                                 const std::string& shell_prefix = "", const std::string& stdout_redirection = "") {
  const auto out = workdir / "stdout.txt", err = workdir / "stderr.txt";
  const std::string capture = stdout_redirection.empty() ? "> '" + out.string() + "'" : stdout_redirection;
  const std::string command = "cd '" + workdir.string() + "' && " + shell_prefix + "'" MOLSURF_CLI_PATH "' " +
                              arguments + " " + capture + " 2> '" + err.string() + "' < /dev/null";
  const int status = std::system(command.c_str());
  CommandResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = read_text(out);
  r.err = read_text(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return r;
}

// A fresh, empty directory under the system temp dir, removed with the object.
class TempDir {
 public:
  TempDir() {
    std::string pattern = (std::filesystem::temp_directory_path() / "molsurf-test-XXXXXX").string();
    path_ = mkdtemp(pattern.data());
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// The number after "key": in a JSON text (the first occurrence).
inline double json_number(const std::string& json, const std::string& key) {
  const std::regex pattern("\"" + key + "\": (-?[0-9.eE+-]+)");
  std::smatch m;
  if (!std::regex_search(json, m, pattern)) throw std::runtime_error("no " + key + " in the JSON");
  return std::stod(m[1]);
}

}  // namespace molsurf::testing
