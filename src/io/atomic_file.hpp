#pragma once
// A file that appears complete or not at all. Data goes to a temporary file beside the
// target (same directory, so the final rename never crosses a file system) and is
// renamed over the target by commit(); if the object dies uncommitted (an exception,
// an early return) the temporary is removed and the old target is left untouched, and
// if a signal ends the process (once detail::remove_temporaries_on_signals() is
// installed) the temporary is removed too. What SIGKILL leaves is removed by the next
// AtomicFile of the same target (temporary_name.hpp).
//
// Only regular files are replaced: a target that is a symbolic link, a directory, a
// device, a pipe or a socket is refused with a message (renaming over a link would
// silently replace the link, and over /dev/null the device node itself).
//
//   AtomicFile out("report.json");
//   out.stream() << text;          // or out.write(text), or hand out.temp_path() to a library
//   out.commit();
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <string_view>
#include <vector>

#include "io/temporary_name.hpp"

namespace molsurf {

class AtomicFile {
 public:
  // Reserves a unique temporary name ".NAME.tmp-PID-N" beside `target` (created empty,
  // exclusively, so concurrent writers never share one; a hash replaces NAME when the name
  // would be too long), after removing the temporaries of `target` that dead processes
  // left. Throws molsurf::Error naming
  // the target and the reason when the directory is missing or not writable, or the
  // target exists and is not a regular file.
  explicit AtomicFile(std::filesystem::path target);
  // The same, with the directory's possible temporaries as `listing` took them (one listing
  // for many targets in one directory).
  AtomicFile(std::filesystem::path target, detail::TemporaryListing& listing);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  const std::filesystem::path& target() const { return target_; }
  // For libraries that want a file name (VTK): they write here, then call commit().
  const std::filesystem::path& temp_path() const { return temp_; }

  // The temporary opened for binary output (opened on first use).
  std::ofstream& stream();
  void write(std::string_view data);

  // Flushes and closes the temporary, checking every write succeeded; after this only
  // the rename is left to do. Throws molsurf::Error when anything failed.
  void finish();
  // finish(), then renames the temporary over the target.
  // Throws molsurf::Error (the temporary is then removed) when anything failed.
  void commit();
  bool committed() const { return committed_; }

 private:
  [[noreturn]] void fail_with_errno(int error_number) const;
  void reserve_temporary(detail::TemporaryListing* listing);  // null: list the directory now

  std::filesystem::path target_;
  std::filesystem::path temp_;
  std::ofstream stream_;
  int registry_slot_ = -1;
  bool committed_ = false;
};

// Throws molsurf::Error unless `target` is absent or a regular file (not a symbolic
// link, directory, device, pipe or socket): what AtomicFile may replace.
void check_replaceable(const std::filesystem::path& target);

// Several files replaced together: each is written to its temporary, and commit()
// renames them only after every one is complete (finish()ed), so a failure while
// writing leaves every old target untouched. A rename itself can still fail midway (a
// full disk does not, but a target directory removed under us does); the Error then
// names the files already replaced and those left as they were.
class AtomicFileSet {
 public:
  AtomicFileSet() = default;
  // With `list_directories` false, no directory is listed for stale temporaries: for a
  // caller that removed its targets' already (molsurf batch, for its jobs).
  explicit AtomicFileSet(bool list_directories) : list_directories_(list_directories) {}
  AtomicFile& add(std::filesystem::path target);
  // Completes every temporary (AtomicFile::finish); throws molsurf::Error, replacing
  // nothing, when one cannot be written. commit() does this first anyway.
  void finish();
  void commit();
  bool empty() const { return files_.empty(); }
  std::vector<std::filesystem::path> targets() const;

 private:
  std::vector<std::unique_ptr<AtomicFile>> files_;  // pointers: add() hands out references
  // Each directory's possible temporaries, listed at its first file.
  std::map<std::filesystem::path, detail::TemporaryListing> listings_;
  bool list_directories_ = true;
};

// The common case: the whole content at once.
void write_file_atomically(const std::filesystem::path& target, std::string_view content);

}  // namespace molsurf
