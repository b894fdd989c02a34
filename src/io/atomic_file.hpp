#pragma once
// A file that appears complete or not at all. Data goes to a temporary file beside the
// target (same directory, so the final rename never crosses a file system) and is
// renamed over the target by commit(); if the object dies uncommitted (an exception,
// an early return) the temporary is removed and the old target is left untouched.
//
//   AtomicFile out("report.json");
//   out.stream() << text;          // or out.write(text), or hand out.temp_path() to a library
//   out.commit();
#include <filesystem>
#include <fstream>
#include <string_view>

namespace molsurf {

class AtomicFile {
 public:
  // Reserves a unique temporary name ".NAME.tmp-PID-N" beside `target` (created empty,
  // exclusively, so concurrent writers never share one). Throws molsurf::Error naming
  // the target and the OS reason when the directory is missing or not writable.
  explicit AtomicFile(std::filesystem::path target);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  const std::filesystem::path& target() const { return target_; }
  // For libraries that want a file name (VTK): they write here, then call commit().
  const std::filesystem::path& temp_path() const { return temp_; }

  // The temporary opened for binary output (opened on first use).
  std::ofstream& stream();
  void write(std::string_view data);

  // Flushes, checks every write succeeded, and renames the temporary over the target.
  // Throws molsurf::Error (the temporary is then removed) when anything failed.
  void commit();
  bool committed() const { return committed_; }

 private:
  [[noreturn]] void fail_with_errno(int error_number) const;

  std::filesystem::path target_;
  std::filesystem::path temp_;
  std::ofstream stream_;
  bool committed_ = false;
};

// The common case: the whole content at once.
void write_file_atomically(const std::filesystem::path& target, std::string_view content);

}  // namespace molsurf
