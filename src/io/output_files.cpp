#include "molsurf/output_files.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <map>
#include <optional>
#include <vector>

#include "io/atomic_file.hpp"
#include "io/mesh_formats.hpp"
#include "io/standard_output.hpp"
#include "io/temporary_registry.hpp"
#include "molsurf/error.hpp"

namespace molsurf {

namespace {

namespace fs = std::filesystem;

// A file's identity: canonical path, plus device and inode when it exists.
struct Identity {
  fs::path canonical;
  std::optional<std::pair<dev_t, ino_t>> node;
};

Identity identify(const fs::path& path) {
  Identity id;
  std::error_code error;
  id.canonical = fs::weakly_canonical(path, error);
  if (error) id.canonical = fs::absolute(path, error).lexically_normal();
  struct stat status {};
  if (::stat(path.c_str(), &status) == 0) id.node = std::pair{status.st_dev, status.st_ino};
  return id;
}

bool same_file(const Identity& a, const Identity& b) {
  if (a.node && b.node) return *a.node == *b.node;
  return a.canonical == b.canonical;
}

std::string quoted(const fs::path& path) { return "'" + path.string() + "'"; }

}  // namespace

void check_output_paths(std::span<const fs::path> inputs, std::span<const OutputRequest> outputs) {
  struct Named {
    fs::path path;
    std::string what;  // "the output of -o", "the input"
    Identity id;
  };
  // Found by device and inode, or by canonical path (same_file): a `.pvtp` of many blocks
  // names thousands of pieces, each looked up here.
  std::vector<Named> taken;
  std::map<std::pair<dev_t, ino_t>, std::size_t> by_node;
  std::multimap<fs::path, std::size_t> by_path;
  auto take = [&](Named named) {
    if (named.id.node) by_node.emplace(*named.id.node, taken.size());
    by_path.emplace(named.id.canonical, taken.size());
    taken.push_back(std::move(named));
  };
  auto taken_as = [&](const Identity& id) -> const Named* {  // the first taken, as named first
    std::size_t first = taken.size();
    if (id.node)
      if (const auto it = by_node.find(*id.node); it != by_node.end()) first = it->second;
    const auto [begin, end] = by_path.equal_range(id.canonical);
    for (auto it = begin; it != end; ++it)
      if (it->second < first && same_file(id, taken[it->second].id)) first = it->second;
    return first < taken.size() ? &taken[first] : nullptr;
  };
  for (const fs::path& input : inputs)
    if (!input.empty()) take({input, "an input file", identify(input)});

  const OutputRequest* standard_output = nullptr;
  for (const OutputRequest& request : outputs) {
    if (request.path.empty())
      throw Error(request.option + " '': an empty file name; name the file to write");
    if (request.path == kStandardOutput) {
      if (request.is_mesh)
        throw Error(request.option + " -: a surface cannot go to standard output (its format follows the file "
                    "extension); name a file");
      if (standard_output)
        throw Error(standard_output->option + " and " + request.option +
                    " both write to standard output ('-'); give one of them a file");
      standard_output = &request;
      continue;
    }
    const std::vector<fs::path> files = request.is_mesh ? mesh_output_files(request.path)
                                                        : std::vector<fs::path>{request.path};
    for (const fs::path& file : files) {
      const std::string role = file == request.path
                                   ? "the output of " + request.option
                                   : "the " + file.extension().string() + " file written with " + request.option +
                                         " " + request.path.string();
      const Identity id = identify(file);
      if (const Named* other = taken_as(id))
        throw Error(request.option + " " + quoted(request.path) + ": " +
                    (file == request.path ? std::string("this") : quoted(file)) + " is " + other->what +
                    (other->path != file ? " (" + quoted(other->path) + ")" : std::string()) +
                    "; refusing to overwrite it: give each output its own file");
      check_replaceable(file);
      const fs::path directory = file.parent_path().empty() ? fs::path(".") : file.parent_path();
      std::error_code error;
      if (!fs::is_directory(directory, error))
        fail(file, "cannot write: directory " + quoted(directory) + " does not exist");
      // A temporary made and removed: whatever would stop the write (a name too long, a
      // read-only directory, no permission) stops the run now, before any work.
      // The write lists the directory for stale temporaries; the probe need not (a
      // directory of a sweep's 200 000 reports takes 40 ms to list).
      detail::TemporaryListing unlisted;
      AtomicFile probe(file, unlisted);
      take({file, role, id});
    }
  }
}

OutputFiles::OutputFiles() : files_(std::make_unique<AtomicFileSet>()) {}
OutputFiles::OutputFiles(bool list_directories) : files_(std::make_unique<AtomicFileSet>(list_directories)) {}
OutputFiles::~OutputFiles() = default;

void OutputFiles::add_mesh(const fs::path& path, const Mesh& mesh, const MeshWriteOptions& options) {
  mesh_io::write_into(*files_, path, mesh, options);
}

void OutputFiles::add_checked_mesh(const fs::path& path, const Mesh& mesh, const MeshWriteOptions& options,
                                   const MeshCheckOptions& check_options) {
  const MeshCheck check = check_mesh(mesh_as_written(mesh, mesh_format_from_path(path), options), check_options);
  if (check.verdict() != MeshCheck::Verdict::valid) {
    std::string defects;
    for (const std::string& defect : check.defects()) defects += (defects.empty() ? "" : "; ") + defect;
    throw Error(path.string() + ": not written: the surface as this file holds it is not valid (" +
                (check.empty() ? std::string("no faces") : defects) + ")");
  }
  add_mesh(path, mesh, options);
}

void OutputFiles::add_text(const fs::path& path, std::string content) {
  if (path == kStandardOutput) {
    standard_output_.push_back(std::move(content));
    return;
  }
  files_->add(path).write(content);
}

std::vector<fs::path> OutputFiles::commit() {
  // Standard output is written between completing the files and replacing them: a report
  // that cannot be written there is an error that leaves every old file as it was.
  files_->finish();
  for (const std::string& text : standard_output_) write_standard_output(text);
  files_->commit();
  std::vector<fs::path> written = files_->targets();
  if (!standard_output_.empty()) written.emplace_back("(standard output)");
  return written;
}

void remove_temporaries_on_signals() { detail::remove_temporaries_on_signals(); }

}  // namespace molsurf
