#pragma once
// The files one run writes: a surface and its reports. They are checked before any work
// (so `--json input.pdb` fails at once, not after the surface), written to temporaries
// beside their targets, and replaced together only when every one is complete: a run
// that fails leaves every old file as it was, and a run that succeeds replaces them all.
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "molsurf/io.hpp"
#include "molsurf/mesh.hpp"
#include "molsurf/mesh_check.hpp"

namespace molsurf {

class AtomicFileSet;

// "-" as an output path: standard output (reports only).
inline constexpr const char* kStandardOutput = "-";

struct OutputRequest {
  std::filesystem::path path;
  std::string option;    // how the user named it, for messages: "-o", "--json"
  bool is_mesh = false;  // a mesh: never "-"; MSMS's .face partner is an output too
};

// Throws molsurf::Error unless every output can be written without harming anything:
// a non-empty name; "-" only for a report, and for one output at most; not the same file
// as an input or another output (compared as canonical paths, and by device and inode for
// files that exist, so "./x", symbolic and hard links count); not a symbolic link,
// directory, device, pipe or socket; in a directory that exists; a name for which a
// temporary can be made there (made and removed: a name too long for the file system or a
// directory without write permission fails here, before any work).
void check_output_paths(std::span<const std::filesystem::path> inputs, std::span<const OutputRequest> outputs);

class OutputFiles {
 public:
  OutputFiles();
  // `list_directories` false: the stale temporaries of the targets were removed already
  // (molsurf batch does, listing its output folder once for all its jobs).
  explicit OutputFiles(bool list_directories);
  ~OutputFiles();
  OutputFiles(const OutputFiles&) = delete;
  OutputFiles& operator=(const OutputFiles&) = delete;

  // Written to temporaries now; nothing replaces its target before commit().
  void add_mesh(const std::filesystem::path& path, const Mesh& mesh, const MeshWriteOptions& options);
  // The same, for a mesh that has not been checked yet (a part of a checked surface, as
  // --split-components writes): checked first as the file will hold it (check_mesh on
  // mesh_as_written), and refused with molsurf::Error naming `path` unless valid.
  void add_checked_mesh(const std::filesystem::path& path, const Mesh& mesh, const MeshWriteOptions& options,
                        const MeshCheckOptions& check_options);
  void add_text(const std::filesystem::path& path, std::string content);  // "-": standard output

  // Completes every temporary, writes what goes to standard output, then replaces every
  // target, and returns the files written, in order. A temporary or standard output that
  // cannot be written throws molsurf::Error with every target left as it was; a rename
  // failing midway throws naming what was written and what was not.
  std::vector<std::filesystem::path> commit();

 private:
  std::unique_ptr<AtomicFileSet> files_;
  std::vector<std::string> standard_output_;
};

// Removes the temporaries of unfinished writes when a signal ends the process (every
// signal that can be caught and is at its default action: SIGINT, SIGTERM, SIGHUP, SIGXFSZ,
// SIGPIPE, ...). For programs (the molsurf command) and the Python module at its import: the
// library's calls do not take signals themselves.
void remove_temporaries_on_signals();

}  // namespace molsurf
