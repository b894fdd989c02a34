// The Python module `molsurf`: converts arguments and results between Python (NumPy
// arrays, paths, gemmi.Structure objects) and libmolsurf. Every rule of the surface job
// lives in the library (compute_surface, read_structure, check_mesh, boolean ...); this
// file only translates, and releases the GIL while the library works.
#include <atomic>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <span>
#include <thread>
#include <exception>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <gemmi/model.hpp>

#include "molsurf/atoms.hpp"
#include "molsurf/boolean.hpp"
#include "molsurf/cancel.hpp"
#include "molsurf/compute_areas.hpp"
#include "molsurf/compute_surface.hpp"
#include "molsurf/error.hpp"
#include "molsurf/gemmi_structure.hpp"
#include "molsurf/input_checks.hpp"
#include "molsurf/io.hpp"
#include "molsurf/mesh.hpp"
#include "molsurf/mesh_check.hpp"
#include "molsurf/output_files.hpp"
#include "molsurf/parameters.hpp"
#include "molsurf/patch_types.hpp"
#include "molsurf/reported_atom_area.hpp"
#include "molsurf/resource_limits.hpp"
#include "molsurf/surface.hpp"
#include "molsurf/surface_files.hpp"
#include "molsurf/surface_report.hpp"
#include "molsurf/threads.hpp"
#include "molsurf/written_check.hpp"

namespace py = pybind11;
using namespace py::literals;

namespace {

using molsurf::Error;

// Vertices are handed to NumPy as an (V, 3) float64 view of the mesh's own memory.
static_assert(sizeof(molsurf::Vec3) == 3 * sizeof(double) && std::is_standard_layout_v<molsurf::Vec3>);
static_assert(sizeof(molsurf::Triangle) == 3 * sizeof(std::uint32_t));

// Results are shared, immutable C++ objects: the NumPy views handed out keep the Python
// object that owns them alive (the array's base), so no array outlives its memory.
struct PyStructure {
  std::shared_ptr<const molsurf::Structure> structure;
};

struct PyMesh {
  std::shared_ptr<const molsurf::Mesh> mesh;
};

struct SurfaceData {
  molsurf::ComputedSurface computed;
  std::shared_ptr<const molsurf::Structure> structure;  // the atoms the face tags index
  molsurf::SphereOptions spheres;
  molsurf::SurfaceKind kind = molsurf::SurfaceKind::sas;
  // The true spheres' numbers as the command reports them (make_exact_report, with
  // outer_only respected); computed.measures holds the facets'.
  molsurf::ExactReport exact;
  std::vector<double> atom_area;  // the command's per-atom area (reported_atom_area)
  std::shared_ptr<const SurfaceData> stern;  // surface(..., stern=probe): the Stern layer
};

struct PySurface {
  std::shared_ptr<const SurfaceData> data;
};

// molsurf.areas(): the true spheres' arrangement only, no mesh (molsurf --areas-only).
struct AreasData {
  std::shared_ptr<const molsurf::Structure> structure;
  molsurf::ExactReport exact;
  std::vector<double> atom_area;
  double probe = 0;
  bool outer_only = false;
  int threads = 1;
};

struct PyAreas {
  std::shared_ptr<const AreasData> data;
};

// molsurf.areas() over a trajectory: (frames, atoms, 3) coordinates with one radius per atom.
// Frame by frame the same numbers as areas() on that frame's coordinates.
struct TrajectoryAreasData {
  std::size_t frames = 0, atoms = 0;
  std::vector<double> area_per_atom;  // frames x atoms, row-major
  std::vector<double> area, volume;   // per frame
  std::vector<double> radii;          // as given, without the probe
  double probe = 0;
  bool outer_only = false;
  int threads = 1;
  double seconds = 0;
};

struct PyTrajectoryAreas {
  std::shared_ptr<const TrajectoryAreasData> data;
};

// A read-only NumPy array over `data`, kept alive by `owner`.
template <class T>
py::array read_only_view(const T* data, std::vector<py::ssize_t> shape, py::handle owner) {
  py::array array(py::dtype::of<T>(), std::move(shape), data, owner);
  py::detail::array_proxy(array.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return array;
}

py::array vertices_view(const molsurf::Mesh& mesh, py::handle owner) {
  return read_only_view(reinterpret_cast<const double*>(mesh.vertices.data()),
                        {static_cast<py::ssize_t>(mesh.vertex_count()), 3}, owner);
}

// Faces as int32 (the library's indices are uint32; a mesh with 2^31 vertices would not
// fit in memory, so every index is a valid int32 and the bits are the same).
py::array faces_view(const molsurf::Mesh& mesh, py::handle owner) {
  if (mesh.vertex_count() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
    throw std::overflow_error("mesh has more vertices than int32 indices can address");
  return read_only_view(reinterpret_cast<const std::int32_t*>(mesh.faces.data()),
                        {static_cast<py::ssize_t>(mesh.face_count()), 3}, owner);
}

py::array tags_view(const molsurf::Mesh& mesh, py::handle owner) {
  if (!mesh.has_tags()) {
    // Untagged faces: -1 each (a fresh array, as there is no memory to view).
    py::array_t<std::int32_t> tags(static_cast<py::ssize_t>(mesh.face_count()));
    std::fill_n(tags.mutable_data(), mesh.face_count(), molsurf::kNoTag);
    return tags;
  }
  return read_only_view(mesh.face_tags.data(), {static_cast<py::ssize_t>(mesh.face_count())}, owner);
}

// ---- arguments -------------------------------------------------------------------------

std::string shape_text(const py::array& a) {
  std::string text = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) text += (i ? ", " : "") + std::to_string(a.shape(i));
  return text + (a.ndim() == 1 ? ",)" : ")");
}

// Numbers only, and no masked entries: NumPy would otherwise convert booleans, drop the
// imaginary part of complex numbers, parse text, truncate float indices and read masked
// entries' hidden values, all silently. Integer targets (indices, tags) take integers only.
template <class T>
py::array_t<T, py::array::c_style | py::array::forcecast> as_array(py::handle value, const char* name) {
  const py::module_ numpy = py::module_::import("numpy");
  if (numpy.attr("ma").attr("is_masked")(value).cast<bool>())
    throw Error(std::string(name) + ": the array has masked entries (numpy.ma); fill or drop them first");
  py::array plain;
  try {
    plain = numpy.attr("asarray")(value);
  } catch (const py::error_already_set&) {
    throw Error(std::string(name) + ": not convertible to a numeric array");
  }
  const char kind = plain.dtype().kind();
  const bool integers = std::is_integral_v<T>;
  if (integers && kind == 'f' && plain.size() > 0) {
    // As a file's reader refuses '1.5' where an index belongs: the first entry that is not
    // whole (or the first entry: a float is no index even when it is whole), in its words.
    const auto values = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(plain);
    const double* data = values.data();
    const std::size_t count = static_cast<std::size_t>(values.size());
    const std::size_t bad = std::find_if(data, data + count, [](double x) { return x != std::trunc(x); }) - data;
    const std::size_t entry = bad < count ? bad : 0;
    const std::vector<std::size_t> shape(values.shape(), values.shape() + values.ndim());
    throw Error(molsurf::array_entry_name(name, entry, shape) + ": " +
                molsurf::integer_text_problem(py::repr(py::float_(data[entry])).cast<std::string>()));
  }
  if (integers ? kind != 'i' && kind != 'u' : kind != 'i' && kind != 'u' && kind != 'f')
    throw Error(std::string(name) + ": not convertible to a numeric array: its elements are " +
                py::str(plain.dtype()).cast<std::string>() +
                (integers ? " (expected integers)" : " (expected integers or floats; booleans, complex numbers, "
                                                     "text and objects are refused)"));
  auto array = py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(plain);
  if (!array) throw Error(std::string(name) + ": not convertible to a numeric array");
  return array;
}

molsurf::Mesh mesh_from_arrays(py::handle vertices, py::handle faces, py::handle tags) {
  const auto v = as_array<double>(vertices, "vertices");
  const auto f = as_array<std::int64_t>(faces, "faces");
  if (v.ndim() != 2 || v.shape(1) != 3)
    throw Error("vertices: expected an array of shape (V, 3), got " + shape_text(v));
  if (f.ndim() != 2 || f.shape(1) != 3) throw Error("faces: expected an array of shape (F, 3), got " + shape_text(f));
  molsurf::Mesh mesh;
  const auto vertex_count = static_cast<std::size_t>(v.shape(0));
  const auto face_count = static_cast<std::size_t>(f.shape(0));
  // What a mesh file's reader refuses, refused in its words.
  const std::size_t vertex_shape[] = {vertex_count, 3};
  molsurf::check_coordinate_array("vertices", std::span(v.data(), 3 * vertex_count), vertex_shape);
  molsurf::check_face_array("faces", std::span(f.data(), 3 * face_count), vertex_count);
  mesh.vertices.resize(vertex_count);
  const double* xyz = v.data();
  for (std::size_t i = 0; i < vertex_count; ++i) mesh.vertices[i] = {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
  mesh.faces.resize(face_count);
  const std::int64_t* index = f.data();
  for (std::size_t i = 0; i < 3 * face_count; ++i) mesh.faces[i / 3][i % 3] = static_cast<molsurf::Index>(index[i]);
  if (!tags.is_none()) {
    // Read as 64 bits, so that a tag beyond 32 bits is refused rather than wrapped.
    const auto t = as_array<std::int64_t>(tags, "tags");
    if (t.ndim() != 1 || static_cast<std::size_t>(t.shape(0)) != face_count)
      throw Error("tags: expected one per face, shape (" + std::to_string(face_count) + ",), got " + shape_text(t));
    mesh.face_tags.resize(face_count);
    for (std::size_t i = 0; i < face_count; ++i) {
      const std::int64_t tag = t.data()[i];
      if (tag < std::numeric_limits<std::int32_t>::min() || tag > std::numeric_limits<std::int32_t>::max())
        throw Error("tags: tags[" + std::to_string(i) + "] is " + std::to_string(tag) +
                    ", beyond 32 bits; a tag is an atom index or -1");
      mesh.face_tags[i] = static_cast<std::int32_t>(tag);
    }
  }
  return mesh;
}

// A Mesh, or a (vertices, faces) pair of arrays.
std::shared_ptr<const molsurf::Mesh> mesh_argument(py::handle value, const char* name) {
  if (py::isinstance<PyMesh>(value)) return value.cast<const PyMesh&>().mesh;
  if ((py::isinstance<py::tuple>(value) || py::isinstance<py::list>(value)) && py::len(value) == 2) {
    const auto pair = py::reinterpret_borrow<py::sequence>(value);
    return std::make_shared<const molsurf::Mesh>(mesh_from_arrays(pair[0], pair[1], py::none()));
  }
  throw Error(std::string(name) + ": expected a molsurf.Mesh or a (vertices, faces) pair of arrays");
}

molsurf::ReadOptions read_options(std::optional<int> model, py::object chains, bool keep_water, bool hydrogens,
                                  bool hetatm, const std::string& radius_set,
                                  std::optional<std::filesystem::path> radius_file) {
  molsurf::ReadOptions options;
  options.model = model;
  if (py::isinstance<py::str>(chains)) options.chains = molsurf::chain_list(chains.cast<std::string>());  // "A,C"
  else if (!chains.is_none()) options.chains = chains.cast<std::vector<std::string>>();
  options.keep_water = keep_water;
  options.keep_hydrogens = hydrogens;
  options.keep_hetatm = hetatm;
  options.radius_set = radius_set;
  if (radius_file) options.radius_file = *radius_file;
  molsurf::validate(options);  // before anything is read
  return options;
}

bool is_gemmi_structure(py::handle value) {
  const py::handle type = reinterpret_cast<PyObject*>(Py_TYPE(value.ptr()));
  return py::str(type.attr("__module__")).cast<std::string>() == "gemmi" &&
         py::str(type.attr("__name__")).cast<std::string>() == "Structure";
}

// The object behind a gemmi.Structure: gemmi's module registers its C++ type with
// pybind11, and modules built with the same compiler and pybind11 ABI share that registry.
const gemmi::Structure& gemmi_structure(py::handle value) {
  try {
    return value.cast<const gemmi::Structure&>();
  } catch (const py::cast_error&) {
    throw py::type_error(
        "this gemmi.Structure comes from a gemmi module built with another pybind11 ABI than molsurf "
        "(use the gemmi of the same distribution, e.g. Debian's python3-gemmi for gemmi-dev), or pass the "
        "file's path instead");
  }
}

// A path (str or os.PathLike) or a gemmi.Structure, read with `options`.
std::shared_ptr<const molsurf::Structure> read_atoms(py::handle source, const molsurf::ReadOptions& options) {
  if (is_gemmi_structure(source)) {
    const gemmi::Structure& st = gemmi_structure(source);
    py::gil_scoped_release release;  // the gemmi.Structure is kept alive by the caller's reference
    return std::make_shared<const molsurf::Structure>(molsurf::structure_from_gemmi(st, options));
  }
  if (!py::isinstance<py::str>(source) && !py::hasattr(source, "__fspath__"))
    throw py::type_error("structure: expected a path, a molsurf.Structure or a gemmi.Structure, not " +
                         py::str(py::type::of(source).attr("__name__")).cast<std::string>());
  const auto path = source.cast<std::filesystem::path>();
  py::gil_scoped_release release;
  return std::make_shared<const molsurf::Structure>(molsurf::read_structure(path, options));
}

PyStructure read_structure_py(py::object source, std::optional<int> model, py::object chains, bool keep_water,
                              bool hydrogens, bool hetatm, const std::string& radius_set,
                              std::optional<std::filesystem::path> radius_file) {
  return {read_atoms(source, read_options(model, std::move(chains), keep_water, hydrogens, hetatm, radius_set,
                                          std::move(radius_file)))};
}

std::shared_ptr<const molsurf::Structure> atoms_from_arrays(py::handle centres, py::handle radii) {
  const auto c = as_array<double>(centres, "centres");
  const auto r = as_array<double>(radii, "radii");
  if (c.ndim() != 2 || c.shape(1) != 3)
    throw Error("centres: expected an array of shape (N, 3), got " + shape_text(c));
  if (r.ndim() != 1 || r.shape(0) != c.shape(0))
    throw Error("radii: expected one per centre, shape (" + std::to_string(c.shape(0)) + ",), got " + shape_text(r));
  auto structure = std::make_shared<molsurf::Structure>();
  const auto n = static_cast<std::size_t>(c.shape(0));
  // What a structure file's reader refuses, refused in its words.
  const std::size_t shape[] = {n, 3};
  molsurf::check_coordinate_array("centres", std::span(c.data(), 3 * n), shape);
  molsurf::check_radius_array("radii", std::span(r.data(), n));
  structure->atoms.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    molsurf::Atom& atom = structure->atoms[i];
    atom.centre = {c.data()[3 * i], c.data()[3 * i + 1], c.data()[3 * i + 2]};
    atom.radius = r.data()[i];
    atom.serial = static_cast<int>(i + 1);
  }
  structure->report.file = "atoms";
  structure->report.format = molsurf::StructureFormat::xyzr;  // spheres as given
  structure->report.records = structure->report.kept = n;
  structure->report.radius_set = "given";
  return structure;
}

// The atoms of surface() and areas(): a path or gemmi.Structure read with the selection
// keywords, a molsurf.Structure as it is, or centres and radii.
std::shared_ptr<const molsurf::Structure> atoms_argument(py::object structure, py::object centres, py::object radii,
                                                         const std::function<molsurf::ReadOptions()>& options) {
  const bool arrays = !centres.is_none() || !radii.is_none();
  if (arrays) {
    if (!structure.is_none()) throw Error("give either a structure or centres and radii, not both");
    if (centres.is_none() || radii.is_none()) throw Error("centres and radii go together");
    return atoms_from_arrays(centres, radii);
  }
  if (structure.is_none())
    throw Error("nothing to compute: give a structure (path, molsurf.Structure, gemmi.Structure) or centres and radii");
  if (py::isinstance<PyStructure>(structure)) return structure.cast<const PyStructure&>().structure;
  return read_atoms(structure, options());
}

// The thread count in the library's range, capped, with a warning, at what this process can
// start (startable_threads, as the command does).
int startable(int threads) {
  molsurf::check(molsurf::kThreadsParameter, threads);
  const molsurf::ThreadCount count = molsurf::startable_threads(threads);
  if (!count.note.empty() && PyErr_WarnEx(PyExc_RuntimeWarning, ("threads: " + count.note).c_str(), 1) != 0)
    throw py::error_already_set();
  return count.threads;
}

// Runs `work` (given a cancel flag) on a worker thread while this thread, which holds the
// GIL, looks for signals every 50 ms with the GIL released in between, so other Python
// threads run meanwhile. Python handles signals on the main thread only, between
// bytecodes: a computation on the main thread would see Ctrl-C only when it returns. On a
// signal the flag is set, the library stops within its current loop step (Cancelled),
// and the signal's exception (KeyboardInterrupt) is raised here.
// `tick`, when given, runs on this thread (with the GIL) at each of those looks and once at
// the end; an exception from it stops the work as a signal does, and is raised here.
void run_interruptibly(const std::function<void(const molsurf::CancelFlag&)>& work,
                       const std::function<void()>& tick = {}) {
  molsurf::CancelFlag cancel{false};
  std::mutex mutex;
  std::condition_variable finished_signal;
  bool finished = false;
  std::exception_ptr failure;
  std::thread worker([&] {
    try {
      work(cancel);
    } catch (...) {
      failure = std::current_exception();
    }
    const std::lock_guard lock(mutex);
    finished = true;
    finished_signal.notify_all();
  });
  bool interrupted = false;
  std::exception_ptr tick_failure;
  while (true) {
    {
      py::gil_scoped_release release;
      std::unique_lock lock(mutex);
      if (finished_signal.wait_for(lock, std::chrono::milliseconds(50), [&] { return finished; })) break;
    }
    if (!interrupted && PyErr_CheckSignals() != 0) {
      interrupted = true;
      cancel.store(true, std::memory_order_relaxed);
    }
    if (!interrupted && !tick_failure && tick) {
      try {
        tick();
      } catch (...) {
        tick_failure = std::current_exception();
        cancel.store(true, std::memory_order_relaxed);
      }
    }
  }
  worker.join();
  if (interrupted) throw py::error_already_set();
  if (tick_failure) std::rethrow_exception(tick_failure);
  if (failure) std::rethrow_exception(failure);
  if (tick) tick();  // the last state
}

// Where a surface job is, as its progress callback last said (written from any thread,
// read by the thread that reports it to Python).
struct ProgressState {
  std::atomic<int> stage{-1};
  std::atomic<std::size_t> done{0}, total{0};
  int reported_stage = -1;
  std::size_t reported_done = ~std::size_t{0};
};

PySurface surface_py(py::object structure, py::object centres, py::object radii, const std::string& surface,
                     std::optional<double> probe, double density, std::optional<int> frequency,
                     const std::string& method, bool cleanup, bool outer_only, bool area_corrected, bool check,
                     int threads, long long max_faces, std::optional<double> max_memory, std::optional<int> model,
                     py::object chains, bool keep_water, bool hydrogens, bool hetatm, const std::string& radius_set,
                     std::optional<std::filesystem::path> radius_file, py::object progress,
                     std::optional<double> stern) {
  // Every parameter judged by the library (parameters.hpp), as the command's options are.
  molsurf::ComputeSurfaceOptions options;
  options.stern_probe = stern;
  options.surface = molsurf::surface_kind_from_name(surface);
  options.spheres.probe = molsurf::surface_probe(options.surface, probe);
  options.spheres.density = density;
  if (frequency) molsurf::check(molsurf::kFrequencyParameter, *frequency);
  options.spheres.frequency = frequency.value_or(0);
  options.spheres.area_corrected = area_corrected;
  options.method = molsurf::surface_method_from_name(method);
  options.threads = threads;
  options.outer_only = outer_only;
  options.cleanup = cleanup;
  options.check_self_intersections = check;
  molsurf::check(molsurf::kMaxFacesParameter, max_faces);
  options.max_sphere_faces = static_cast<std::uint64_t>(max_faces);
  if (max_memory) options.max_memory = molsurf::memory_limit_bytes(*max_memory);
  molsurf::validate(options);
  options.threads = startable(threads);
  if (!progress.is_none() && !PyCallable_Check(progress.ptr()))
    throw Error("progress: must be callable as progress(stage, done, total), or None");

  // Arrays too large for the limits are refused from their radii alone, before any atom
  // is built (ten million atoms took 4 GB and most of a minute to be refused after).
  if (structure.is_none() && !centres.is_none() && !radii.is_none()) {
    const auto r = as_array<double>(radii, "radii");
    if (r.ndim() == 1 &&
        std::all_of(r.data(), r.data() + r.size(), [](double x) { return molsurf::radius_problem(x).empty(); }))
      molsurf::check_sphere_faces("atoms", molsurf::estimate_resources(std::span(r.data(), r.size()), options.spheres),
                                  options.spheres, options.max_sphere_faces);
  }
  auto data = std::make_shared<SurfaceData>();
  data->structure = atoms_argument(structure, centres, radii, [&] {
    molsurf::ReadOptions read =
        read_options(model, chains, keep_water, hydrogens, hetatm, radius_set, std::move(radius_file));
    read.max_memory = options.max_memory;
    return read;
  });
  options.source = data->structure->report.file;
  data->spheres = options.spheres;
  data->kind = options.surface;
  // progress(stage, done, total): called on this thread, with the latest state, each time
  // it changed (at most 20 times a second).
  ProgressState state;
  std::function<void()> tick;
  if (!progress.is_none()) {
    options.progress = [&state](molsurf::SurfaceStage stage, std::size_t done, std::size_t total) {
      state.done.store(done, std::memory_order_relaxed);
      state.total.store(total, std::memory_order_relaxed);
      state.stage.store(static_cast<int>(stage), std::memory_order_relaxed);
    };
    tick = [&state, &progress] {
      const int stage = state.stage.load(std::memory_order_relaxed);
      const std::size_t done = state.done.load(std::memory_order_relaxed);
      if (stage < 0 || (stage == state.reported_stage && done == state.reported_done)) return;
      state.reported_stage = stage;
      state.reported_done = done;
      progress(molsurf::surface_stage_name(static_cast<molsurf::SurfaceStage>(stage)), done,
               state.total.load(std::memory_order_relaxed));
    };
  }
  run_interruptibly([&](const molsurf::CancelFlag& cancel) {
    options.cancel = &cancel;
    data->computed = molsurf::compute_surface(data->structure->atoms, options);
    // The true spheres' numbers, as the command's report and CSV tables give them.
    if (options.surface == molsurf::SurfaceKind::ses) {
      // As the command's report: the SES's area, volume and per-atom areas are its patches'
      // (exact), the facets' in facet_area and facet_volume.
      const molsurf::ReportedTotals totals = molsurf::reported_totals(data->computed, data->computed.measures);
      data->exact.area = totals.area;
      data->exact.volume = totals.volume;
    } else {
      data->exact = molsurf::make_exact_report(data->computed.exact, data->computed.component_shells, outer_only);
    }
    data->atom_area = molsurf::reported_atom_area(data->computed, outer_only);
    if (data->computed.stern) {  // the Stern layer: a surface of its own, the SAS at its probe
      auto layer = std::make_shared<SurfaceData>();
      layer->computed = *data->computed.stern;
      layer->structure = data->structure;
      layer->spheres = options.spheres;
      layer->spheres.probe = *stern;
      layer->kind = molsurf::SurfaceKind::sas;
      layer->exact = molsurf::make_exact_report(layer->computed.exact, layer->computed.component_shells, outer_only);
      layer->atom_area = molsurf::reported_atom_area(layer->computed, outer_only);
      data->stern = std::move(layer);
    }
  }, tick);
  return {std::move(data)};
}

PyAreas areas_single(py::object structure, py::object centres, py::object radii, double probe, bool outer_only,
                 int threads, std::optional<int> model, py::object chains, bool keep_water, bool hydrogens,
                 bool hetatm, const std::string& radius_set, std::optional<std::filesystem::path> radius_file) {
  molsurf::check(molsurf::kProbeParameter, probe);
  threads = startable(threads);
  auto data = std::make_shared<AreasData>();
  data->structure = atoms_argument(structure, centres, radii, [&] {
    return read_options(model, chains, keep_water, hydrogens, hetatm, radius_set, std::move(radius_file));
  });
  data->probe = probe;
  data->outer_only = outer_only;
  data->threads = threads > 0 ? threads : omp_get_max_threads();
  molsurf::SphereOptions spheres;
  spheres.probe = probe;
  try {
    py::gil_scoped_release release;
    const molsurf::ComputedAreas computed = molsurf::compute_areas(data->structure->atoms, spheres, threads);
    data->exact = molsurf::make_exact_report(computed.arrangement, {}, outer_only);
    data->exact.seconds = computed.seconds;
    data->atom_area = molsurf::exact_atom_area(computed.arrangement, outer_only);
  } catch (const std::invalid_argument& e) {
    throw Error(e.what());  // arrange_spheres' refusals (too many spheres, bad numbers)
  }
  return {std::move(data)};
}


// The coordinates of every frame and one radius per atom, checked as atoms_from_arrays checks
// one frame's; then the frames in parallel, each frame's arrangement on one thread (so the
// result does not depend on the thread count: every frame's numbers are those of areas() on
// its coordinates, which do not depend on it either).
PyTrajectoryAreas trajectory_areas(py::handle coords, py::handle radii, double probe, bool outer_only, int threads) {
  const auto c = as_array<double>(coords, "coords");
  const auto r = as_array<double>(radii, "radii");
  if (c.ndim() != 3 || c.shape(2) != 3)
    throw Error("coords: expected an array of shape (frames, atoms, 3), got " + shape_text(c));
  if (r.ndim() != 1 || r.shape(0) != c.shape(1))
    throw Error("radii: expected one per atom, shape (" + std::to_string(c.shape(1)) + ",), got " + shape_text(r));
  auto data = std::make_shared<TrajectoryAreasData>();
  data->frames = static_cast<std::size_t>(c.shape(0));
  data->atoms = static_cast<std::size_t>(c.shape(1));
  data->probe = probe;
  data->outer_only = outer_only;
  data->radii.assign(r.data(), r.data() + data->atoms);
  molsurf::check_radius_array("radii", data->radii);
  const double* xyz = c.data();
  const std::size_t shape[] = {data->frames, data->atoms, 3};
  molsurf::check_coordinate_array("coords", std::span(xyz, 3 * data->frames * data->atoms), shape);
  const int max_threads = threads > 0 ? threads : omp_get_max_threads();
  data->threads = static_cast<int>(std::max<std::size_t>(1, std::min<std::size_t>(max_threads, data->frames)));
  data->area_per_atom.assign(data->frames * data->atoms, 0.0);
  data->area.assign(data->frames, 0.0);
  data->volume.assign(data->frames, 0.0);
  molsurf::SphereOptions spheres;
  spheres.probe = probe;
  {
    // The array `c` (kept alive here) is read, never written, while the GIL is released.
    py::gil_scoped_release release;
    const auto start = std::chrono::steady_clock::now();
    const std::size_t n = data->atoms;
    TrajectoryAreasData& d = *data;
    const auto set_frame = [&](std::size_t f, std::vector<molsurf::Atom>& atoms) {
      if (atoms.size() != n) {
        atoms.assign(n, {});
        for (std::size_t i = 0; i < n; ++i) {
          atoms[i].radius = d.radii[i];
          atoms[i].serial = static_cast<int>(i + 1);
        }
      }
      const double* frame = xyz + 3 * n * f;
      for (std::size_t i = 0; i < n; ++i) atoms[i].centre = {frame[3 * i], frame[3 * i + 1], frame[3 * i + 2]};
    };
    const std::vector<molsurf::FrameAreas> computed =
        molsurf::compute_frame_areas(d.frames, set_frame, spheres, outer_only, d.threads);
    for (std::size_t f = 0; f < d.frames; ++f) {
      d.area[f] = computed[f].area;
      d.volume[f] = computed[f].volume;
      std::copy(computed[f].atom_area.begin(), computed[f].atom_area.end(),
                d.area_per_atom.begin() + static_cast<std::ptrdiff_t>(n * f));
    }
    d.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return {std::move(data)};
}

// areas(): one structure or set of centres -> Areas; coordinates of shape (frames, atoms, 3)
// -> TrajectoryAreas. `coords` is another name for `centres`, and a NumPy array given in the
// structure's place is taken as coordinates too.
py::object areas_py(py::object structure, py::object centres, py::object coords, py::object radii, double probe,
                    bool outer_only, int threads, std::optional<int> model, py::object chains, bool keep_water,
                    bool hydrogens, bool hetatm, const std::string& radius_set,
                    std::optional<std::filesystem::path> radius_file) {
  if (!coords.is_none() && !centres.is_none()) throw Error("give either centres or coords (the same argument), not both");
  const char* name = coords.is_none() && !centres.is_none() ? "centres" : "coords";
  if (coords.is_none()) coords = centres;
  if (py::isinstance<py::array>(structure)) {
    if (!coords.is_none()) throw Error("coordinates given twice: as the first argument and as centres/coords");
    coords = structure;
    structure = py::none();
  }
  if (!coords.is_none() && structure.is_none() && !radii.is_none()) {
    const auto c = as_array<double>(coords, name);
    if (c.ndim() > 3)  // fewer dimensions: the one-frame check below names the expected shape
      throw Error(std::string(name) + ": expected an array of shape (N, 3) or (frames, atoms, 3), got " +
                  shape_text(c));
    if (c.ndim() == 3) {
      molsurf::check(molsurf::kProbeParameter, probe);
      threads = startable(threads);
      return py::cast(trajectory_areas(c, radii, probe, outer_only, threads));
    }
    coords = c;
  }
  return py::cast(areas_single(std::move(structure), std::move(coords), std::move(radii), probe, outer_only, threads,
                               model, std::move(chains), keep_water, hydrogens, hetatm, radius_set,
                               std::move(radius_file)));
}

// ---- results -----------------------------------------------------------------------------

py::object string_array(const std::vector<std::string>& values) {
  return py::module_::import("numpy").attr("array")(py::cast(values), "dtype"_a = "str");
}

template <class T, class Get>
py::array_t<T> atom_column(const molsurf::Structure& s, Get get) {
  py::array_t<T> out(static_cast<py::ssize_t>(s.atoms.size()));
  T* values = out.mutable_data();
  for (std::size_t i = 0; i < s.atoms.size(); ++i) values[i] = static_cast<T>(get(s.atoms[i]));
  return out;
}

template <class Get>
py::object label_column(const molsurf::Structure& s, Get get) {
  std::vector<std::string> values;
  values.reserve(s.atoms.size());
  for (const molsurf::Atom& atom : s.atoms) values.push_back(get(atom));
  return string_array(values);
}

std::string icode_text(char icode) { return icode == ' ' || icode == '\0' ? std::string() : std::string(1, icode); }

const char* format_name(molsurf::StructureFormat format) {
  switch (format) {
    case molsurf::StructureFormat::pdb: return "pdb";
    case molsurf::StructureFormat::mmcif: return "mmcif";
    case molsurf::StructureFormat::pqr: return "pqr";
    case molsurf::StructureFormat::xyzr: return "xyzr";
  }
  return "?";
}

py::dict read_report_dict(const molsurf::ReadReport& r) {
  return py::dict("file"_a = r.file.string(), "format"_a = format_name(r.format),
                  "models_in_file"_a = r.models_in_file, "model_used"_a = r.model_used, "records"_a = r.records,
                  "kept"_a = r.kept, "dropped_water"_a = r.dropped_water, "dropped_hydrogen"_a = r.dropped_hydrogen,
                  "dropped_altloc"_a = r.dropped_altloc, "dropped_hetatm"_a = r.dropped_hetatm,
                  "dropped_chain"_a = r.dropped_chain, "kept_by_element"_a = r.kept_by_element,
                  "radius_set"_a = r.radius_set, "radius_from_element"_a = r.radius_from_element,
                  "radius_default"_a = r.radius_default, "fallback_examples"_a = r.fallback_examples);
}

py::object residue_table(const molsurf::Structure& s, const std::vector<double>& atom_area) {
  const std::vector<molsurf::ResidueArea> rows = molsurf::area_per_residue(s.atoms, atom_area);
  std::size_t chain_width = 1, name_width = 1;
  py::list records;
  for (const molsurf::ResidueArea& r : rows) {
    chain_width = std::max(chain_width, r.chain.size());
    name_width = std::max(name_width, r.residue_name.size());
    records.append(py::make_tuple(r.chain, r.residue_name, r.residue_number, icode_text(r.insertion_code), r.atoms,
                                  r.area));
  }
  py::list dtype;
  dtype.append(py::make_tuple("chain", "U" + std::to_string(chain_width)));
  dtype.append(py::make_tuple("residue_name", "U" + std::to_string(name_width)));
  dtype.append(py::make_tuple("residue_number", "i8"));
  dtype.append(py::make_tuple("insertion_code", "U1"));
  dtype.append(py::make_tuple("atoms", "i8"));
  dtype.append(py::make_tuple("area", "f8"));
  return py::module_::import("numpy").attr("array")(records, "dtype"_a = dtype);
}

// The library's write of a surface's file (surface_files.hpp), as the command writes it.
std::vector<std::filesystem::path> write_surface(const SurfaceData& d, const std::filesystem::path& path, bool ascii,
                                                 int msms_decimals, bool msms_header) {
  const molsurf::SurfaceFileOptions file{.ascii = ascii, .msms_header = msms_header, .msms_decimals = msms_decimals};
  const molsurf::WrittenSurface written = molsurf::write_surface(
      path, d.computed,
      molsurf::surface_write_options(d.kind, d.spheres, d.structure->atoms, d.structure->report.file, file));
  if (!written.note.empty()) {
    py::gil_scoped_acquire acquire;
    py::module_::import("warnings").attr("warn")(written.note);
  }
  return written.files;
}

py::dict cleanup_dict(const molsurf::CleanupStats& c) {
  return py::dict("collapses"_a = c.collapses, "flips"_a = c.flips, "moves"_a = c.moves, "refused"_a = c.refused,
                  "area_before"_a = c.area_before, "area_after"_a = c.area_after,
                  "min_angle_before"_a = c.before.min_angle_deg, "min_angle_after"_a = c.after.min_angle_deg);
}

// What the arrangement of the true spheres holds (the JSON report's "arrangement").
py::dict arrangement_dict(const molsurf::ExactReport& e) {
  return py::dict("vertices"_a = e.vertices, "arcs"_a = e.arcs, "buried_atoms"_a = e.buried_atoms,
                  "exact_decisions"_a = e.exact_decisions, "degenerate_points"_a = e.degenerate_points);
}

// For each mesh component, the index into `shells` of the true shell it follows, or None.
py::list component_shells_list(const SurfaceData& d) {
  py::list out;
  for (const std::int64_t s : d.computed.component_shells) {
    if (s >= 0 && static_cast<std::size_t>(s) < d.exact.shells.size()) out.append(s);
    else out.append(py::none());
  }
  return out;
}

}  // namespace

PYBIND11_MODULE(molsurf, m) {
  // A signal that ends the interpreter while a surface is written (SIGTERM from a job
  // scheduler) must not leave the write's temporary; signals Python handles or ignores
  // itself (SIGINT, SIGPIPE, SIGXFSZ) are left to it.
  molsurf::remove_temporaries_on_signals();
  // pybind11 2.10 fills its table of NumPy's C API in a function-local static on first use,
  // importing numpy.core.multiarray inside it. An import lets other threads take the GIL, so
  // two Python threads making their first molsurf calls at once deadlock: one waits for the
  // GIL inside the static, the other holds the GIL and waits for the static. Filled here, at
  // import, it is never filled concurrently.
  py::detail::npy_api::get();
  m.doc() =
      "Exact, watertight molecular surfaces (libmolsurf from Python).\n\n"
      "Lengths are in angstrom (A), areas in A^2, volumes in A^3. Arrays are NumPy arrays:\n"
      "geometry of a result (vertices, faces, atom_of_face, area_per_atom, facet_area_per_atom) is a\n"
      "read-only view of the result's own memory (np.array(x) copies it); everything else is a fresh\n"
      "copy. area, volume and the per-atom areas are the true spheres' (exact, as the command reports\n"
      "them); facet_* are the mesh's own.\n"
      "Every library error raises molsurf.Error (a RuntimeError) with the library's message.";
  m.attr("__version__") = MOLSURF_VERSION;
  py::register_exception<Error>(m, "Error", PyExc_RuntimeError);

  // ---- Structure ----
  py::class_<PyStructure>(m, "Structure",
                          "Atoms read from a structure file: the selected model, filtered and given radii.\n"
                          "Every array property is a fresh copy, one row per atom.")
      .def("__len__", [](const PyStructure& s) { return s.structure->atoms.size(); })
      .def_property_readonly(
          "centres",
          [](const PyStructure& s) {
            py::array_t<double> out({static_cast<py::ssize_t>(s.structure->atoms.size()), py::ssize_t{3}});
            double* xyz = out.mutable_data();
            for (const molsurf::Atom& a : s.structure->atoms) {
              *xyz++ = a.centre.x;
              *xyz++ = a.centre.y;
              *xyz++ = a.centre.z;
            }
            return out;
          },
          "Atom centres, (N, 3) float64, A (copy).")
      .def_property_readonly(
          "radii", [](const PyStructure& s) { return atom_column<double>(*s.structure, [](auto& a) { return a.radius; }); },
          "Van der Waals radii without the probe, (N,) float64, A (copy).")
      .def_property_readonly(
          "elements", [](const PyStructure& s) { return label_column(*s.structure, [](auto& a) { return a.element; }); },
          "Element symbols, upper case, (N,) str (copy).")
      .def_property_readonly(
          "atom_names",
          [](const PyStructure& s) { return label_column(*s.structure, [](auto& a) { return a.atom_name; }); },
          "Atom names, e.g. 'CA', (N,) str (copy).")
      .def_property_readonly(
          "residue_names",
          [](const PyStructure& s) { return label_column(*s.structure, [](auto& a) { return a.residue_name; }); },
          "Residue names, e.g. 'ALA', (N,) str (copy).")
      .def_property_readonly(
          "residue_numbers",
          [](const PyStructure& s) {
            return atom_column<std::int64_t>(*s.structure, [](auto& a) { return a.residue_number; });
          },
          "Residue sequence numbers, (N,) int32 (copy).")
      .def_property_readonly(
          "insertion_codes",
          [](const PyStructure& s) {
            return label_column(*s.structure, [](auto& a) { return icode_text(a.insertion_code); });
          },
          "Insertion codes ('' when blank), (N,) str (copy).")
      .def_property_readonly(
          "chains", [](const PyStructure& s) { return label_column(*s.structure, [](auto& a) { return a.chain; }); },
          "Chain names, (N,) str (copy).")
      .def_property_readonly(
          "serials",
          [](const PyStructure& s) { return atom_column<std::int32_t>(*s.structure, [](auto& a) { return a.serial; }); },
          "Atom serial numbers as in the file (0 where the format has none), (N,) int32 (copy).")
      .def_property_readonly(
          "hetero", [](const PyStructure& s) { return atom_column<bool>(*s.structure, [](auto& a) { return a.hetero; }); },
          "Whether each atom is a hetero atom (ligand, ion, water), (N,) bool (copy).")
      .def_property_readonly(
          "occupancies",
          [](const PyStructure& s) { return atom_column<double>(*s.structure, [](auto& a) { return a.occupancy; }); },
          "Occupancies, (N,) float64 (copy).")
      .def_property_readonly(
          "b_factors",
          [](const PyStructure& s) { return atom_column<double>(*s.structure, [](auto& a) { return a.b_factor; }); },
          "B-factors, (N,) float64, A^2 (copy).")
      .def_property_readonly(
          "charges",
          [](const PyStructure& s) { return atom_column<double>(*s.structure, [](auto& a) { return a.charge; }); },
          "PQR partial charges (0 for other formats), (N,) float64, e (copy).")
      .def_property_readonly(
          "report", [](const PyStructure& s) { return read_report_dict(s.structure->report); },
          "What the reader kept, dropped and guessed (dict): records, kept, dropped_water, dropped_hydrogen,\n"
          "dropped_altloc, dropped_hetatm, dropped_chain, model_used, models_in_file, radius_set, ...")
      .def("__repr__", [](const PyStructure& s) {
        return "<molsurf.Structure " + s.structure->report.file.string() + ": " +
               std::to_string(s.structure->atoms.size()) + " atoms>";
      });

  m.def("read_structure", &read_structure_py, "source"_a, py::kw_only(), "model"_a = py::none(), "chains"_a = py::none(),
        "keep_water"_a = false, "hydrogens"_a = false, "hetatm"_a = true, "radius_set"_a = "protor",
        "radius_file"_a = py::none(),
        "read_structure(source, *, model=None, chains=None, keep_water=False, hydrogens=False, hetatm=True,\n"
        "               radius_set='protor', radius_file=None) -> Structure\n\n"
        "Reads atoms from a path: PDB (.pdb .ent), mmCIF (.cif .mmcif), either gzipped (.gz), PQR (.pqr,\n"
        "radii from the file) or MSMS .xyzr; or from a gemmi.Structure in memory (no file written).\n"
        "The command line's selection rules apply:\n"
        "  model: model number as written in the file (default: the first);\n"
        "  chains: chain names to keep, a list or 'A,C' (default: all);\n"
        "  keep_water, hydrogens: keep waters / hydrogen and deuterium atoms (dropped by default);\n"
        "  hetatm: keep ligands, ions and cofactors (default True);\n"
        "  radius_set: 'protor' (default) or 'bondi'; radius_file: a user table overriding it.\n"
        "One conformer per atom (blank altloc, or the highest occupancy). Raises molsurf.Error naming\n"
        "file and line for unreadable input or an empty selection.");

  // ---- Mesh and check ----
  py::class_<molsurf::ComponentMeasure>(m, "Component",
                                        "One connected part of a surface: the outer surface or a cavity.")
      .def_readonly("faces", &molsurf::ComponentMeasure::faces, "Number of faces.")
      .def_readonly("area", &molsurf::ComponentMeasure::area, "Area, A^2.")
      .def_readonly("volume", &molsurf::ComponentMeasure::volume,
                    "Signed volume, A^3: negative for a cavity (its faces point into it).")
      .def_property_readonly("cavity", &molsurf::ComponentMeasure::cavity, "Whether this is a cavity.")
      .def("__repr__", [](const molsurf::ComponentMeasure& c) {
        return std::string("<molsurf.Component ") + (c.cavity() ? "cavity" : "outer") + ": " +
               std::to_string(c.faces) + " faces, area " + std::to_string(c.area) + " A^2, volume " +
               std::to_string(c.volume) + " A^3>";
      });

  py::class_<molsurf::Quality>(m, "Quality", "Triangle quality of a mesh.")
      .def_readonly("min_angle_deg", &molsurf::Quality::min_angle_deg, "Smallest angle over all faces, degrees.")
      .def_readonly("mean_min_angle_deg", &molsurf::Quality::mean_min_angle_deg,
                    "Mean of each face's smallest angle, degrees.")
      .def_readonly("max_aspect_ratio", &molsurf::Quality::max_aspect_ratio,
                    "Largest longest-edge / (2 sqrt(3) inradius); 1 for an equilateral triangle.")
      .def_readonly("below_1deg", &molsurf::Quality::below_1deg, "Faces whose smallest angle is below 1 degree.")
      .def_readonly("below_5deg", &molsurf::Quality::below_5deg, "Faces whose smallest angle is below 5 degrees.")
      .def_readonly("faces", &molsurf::Quality::faces, "Faces measured.")
      .def("__repr__", [](const molsurf::Quality& q) {
        return "<molsurf.Quality min angle " + std::to_string(q.min_angle_deg) + " deg, " +
               std::to_string(q.below_5deg) + " of " + std::to_string(q.faces) + " faces under 5 deg>";
      });

  py::class_<molsurf::MeshCheck>(m, "Check",
                                 "What molsurf check finds on a mesh; every decision exact. `valid` means closed,\n"
                                 "2-manifold, oriented outward, no degenerate face, no self-intersection.")
      .def_property_readonly("valid", &molsurf::MeshCheck::valid, "No defect (also true for an empty mesh).")
      .def_property_readonly("empty", &molsurf::MeshCheck::empty, "No faces.")
      .def_property_readonly("closed", &molsurf::MeshCheck::closed, "No boundary or non-manifold edge.")
      .def_property_readonly("manifold", &molsurf::MeshCheck::manifold, "2-manifold at every edge and vertex.")
      .def_property_readonly("oriented", &molsurf::MeshCheck::oriented, "Neighbouring faces agree on orientation.")
      .def_property_readonly("defects", &molsurf::MeshCheck::defects, "One line per defect found (list of str).")
      .def_readonly("vertices", &molsurf::MeshCheck::vertices)
      .def_readonly("faces", &molsurf::MeshCheck::faces)
      .def_readonly("edges", &molsurf::MeshCheck::edges)
      .def_readonly("unused_vertices", &molsurf::MeshCheck::unused_vertices)
      .def_readonly("boundary_edges", &molsurf::MeshCheck::boundary_edges, "Edges of one face: holes.")
      .def_readonly("nonmanifold_edges", &molsurf::MeshCheck::nonmanifold_edges, "Edges of more than two faces.")
      .def_readonly("misoriented_edges", &molsurf::MeshCheck::misoriented_edges)
      .def_readonly("nonmanifold_vertices", &molsurf::MeshCheck::nonmanifold_vertices)
      .def_readonly("degenerate_faces", &molsurf::MeshCheck::degenerate_faces)
      .def_readonly("duplicate_faces", &molsurf::MeshCheck::duplicate_faces)
      .def_readonly("intersecting_pairs", &molsurf::MeshCheck::intersecting_pairs, "Face pairs that cross.")
      .def_readonly("contact_pairs", &molsurf::MeshCheck::contact_pairs, "Face pairs that only touch.")
      .def_readonly("defect_pairs_capped", &molsurf::MeshCheck::defect_pairs_capped,
                    "Counting stopped at 100 000 intersecting or touching pairs: the counts are lower bounds.")
      .def_readonly("non_finite_vertices", &molsurf::MeshCheck::non_finite_vertices)
      .def_readonly("self_intersections_checked", &molsurf::MeshCheck::self_intersections_checked)
      .def_readonly("components", &molsurf::MeshCheck::components)
      .def_readonly("inward_components", &molsurf::MeshCheck::inward_components)
      .def_readonly("euler_characteristic", &molsurf::MeshCheck::euler_characteristic)
      .def_readonly("area", &molsurf::MeshCheck::area, "A^2.")
      .def_readonly("volume", &molsurf::MeshCheck::volume, "A^3.")
      .def_readonly("quality", &molsurf::MeshCheck::quality)
      .def(
          "to_dict",
          [](const molsurf::MeshCheck& c) {
            return py::dict("valid"_a = c.valid(), "empty"_a = c.empty(), "closed"_a = c.closed(),
                            "manifold"_a = c.manifold(), "oriented"_a = c.oriented(), "vertices"_a = c.vertices,
                            "faces"_a = c.faces, "edges"_a = c.edges, "unused_vertices"_a = c.unused_vertices,
                            "boundary_edges"_a = c.boundary_edges, "nonmanifold_edges"_a = c.nonmanifold_edges,
                            "misoriented_edges"_a = c.misoriented_edges,
                            "nonmanifold_vertices"_a = c.nonmanifold_vertices,
                            "degenerate_faces"_a = c.degenerate_faces, "duplicate_faces"_a = c.duplicate_faces,
                            "intersecting_pairs"_a = c.intersecting_pairs, "contact_pairs"_a = c.contact_pairs, "defect_pairs_capped"_a = c.defect_pairs_capped,
                            "non_finite_vertices"_a = c.non_finite_vertices,
                            "self_intersections_checked"_a = c.self_intersections_checked,
                            "components"_a = c.components, "inward_components"_a = c.inward_components,
                            "euler_characteristic"_a = c.euler_characteristic, "area"_a = c.area,
                            "volume"_a = c.volume, "defects"_a = c.defects());
          },
          "The findings as a dict.")
      .def("__repr__", [](const molsurf::MeshCheck& c) {
        return std::string("<molsurf.Check ") + (c.valid() ? (c.empty() ? "empty" : "valid") : "invalid") + ": " +
               std::to_string(c.faces) + " faces, " + std::to_string(c.defects().size()) + " defects>";
      });

  py::class_<PyMesh>(m, "Mesh",
                     "An indexed triangle mesh, faces counter-clockwise seen from outside.\n"
                     "Mesh(vertices, faces, tags=None) copies (V, 3) float coordinates (A), (F, 3) integer\n"
                     "vertex indices and optional (F,) int32 face tags; the properties are read-only views.")
      .def(py::init([](py::object vertices, py::object faces, py::object tags) {
             return PyMesh{std::make_shared<const molsurf::Mesh>(mesh_from_arrays(vertices, faces, tags))};
           }),
           "vertices"_a, "faces"_a, "tags"_a = py::none())
      .def_property_readonly(
          "vertices", [](py::object self) { return vertices_view(*self.cast<const PyMesh&>().mesh, self); },
          "(V, 3) float64, A: read-only view.")
      .def_property_readonly(
          "faces", [](py::object self) { return faces_view(*self.cast<const PyMesh&>().mesh, self); },
          "(F, 3) int32 vertex indices, counter-clockwise from outside: read-only view.")
      .def_property_readonly(
          "tags", [](py::object self) { return tags_view(*self.cast<const PyMesh&>().mesh, self); },
          "(F,) int32 face tags (atom index for a surface, the source face's tag after a Boolean; -1:\n"
          "untagged): read-only view, or a fresh array of -1 for an untagged mesh.")
      .def_property_readonly(
          "area", [](const PyMesh& m) { return molsurf::surface_area(*m.mesh); }, "Total area, A^2.")
      .def_property_readonly(
          "volume", [](const PyMesh& m) { return molsurf::signed_volume(*m.mesh); },
          "Signed enclosed volume, A^3 (positive for a closed outward mesh).")
      .def(
          "write",
          [](const PyMesh& m, const std::filesystem::path& path, bool ascii) {
            const std::vector<molsurf::OutputRequest> outputs{{path, "path", true}};
            molsurf::check_output_paths({}, outputs);
            molsurf::MeshWriteOptions options;
            options.ascii = ascii;
            options.msms_decimals = molsurf::kMsmsExact;
            py::gil_scoped_release release;
            molsurf::write_mesh(path, *m.mesh, options);
          },
          "path"_a, "ascii"_a = false,
          "Writes the mesh; the format follows the extension: .vtp .vtk .ply .off .stl .obj .vert (MSMS\n"
          ".vert/.face pair, exact coordinates) .msh (gmsh 2.2). ascii: text .ply/.stl. Atomic.")
      .def("__repr__", [](const PyMesh& m) {
        return "<molsurf.Mesh: " + std::to_string(m.mesh->vertex_count()) + " vertices, " +
               std::to_string(m.mesh->face_count()) + " faces>";
      });

  m.def(
      "read_mesh",
      [](const std::filesystem::path& path) {
        py::gil_scoped_release release;
        return PyMesh{std::make_shared<const molsurf::Mesh>(molsurf::read_mesh(path))};
      },
      "path"_a,
      "read_mesh(path) -> Mesh\n\n"
      "Reads .stl (ASCII/binary) .off .ply .obj .vtk .vtp and MSMS .vert/.face; face tags are read back\n"
      "when present. Raises molsurf.Error naming file and line.");

  m.def(
      "check",
      [](py::object mesh_or_vertices, py::object faces, bool self_intersections) {
        const auto mesh = faces.is_none()
                              ? mesh_argument(mesh_or_vertices, "mesh")
                              : std::make_shared<const molsurf::Mesh>(mesh_from_arrays(mesh_or_vertices, faces, py::none()));
        molsurf::MeshCheckOptions options;
        options.self_intersections = self_intersections;
        py::gil_scoped_release release;
        return molsurf::check_mesh(*mesh, options);
      },
      "mesh_or_vertices"_a, "faces"_a = py::none(), py::kw_only(), "self_intersections"_a = true,
      "check(vertices, faces, *, self_intersections=True) -> Check\n"
      "check(mesh) -> Check\n\n"
      "The findings of `molsurf check` on a mesh given as (V, 3) vertices (A) and (F, 3) indices, or as a\n"
      "Mesh: closed, manifold, oriented, outward, degenerate faces, exact self-intersections.");

  m.def(
      "boolean",
      [](const std::string& op, py::object a, py::object b) {
        const molsurf::BooleanOp operation = molsurf::boolean_op_from_name(op);
        const auto mesh_a = mesh_argument(a, "a");
        const auto mesh_b = mesh_argument(b, "b");
        py::gil_scoped_release release;
        // The operands held to the engine's contract and the result checked, as `molsurf boolean` does.
        molsurf::CheckedBoolean r = molsurf::checked_boolean(*mesh_a, *mesh_b, operation, "a", "b");
        if (std::string problem = r.problem(r.check); !problem.empty()) throw Error(problem);
        if (const std::string note = molsurf::boolean_note(r.result.stats); !note.empty()) {
          py::gil_scoped_acquire acquire;
          if (PyErr_WarnEx(PyExc_UserWarning, note.c_str(), 1) != 0) throw py::error_already_set();
        }
        return PyMesh{std::make_shared<const molsurf::Mesh>(std::move(r.result.mesh))};
      },
      "op"_a, "a"_a, "b"_a,
      "boolean(op, a, b) -> Mesh\n\n"
      "The exact union, intersection or difference (a minus b) of two closed meshes, each a Mesh or a\n"
      "(vertices, faces) pair of arrays. Both must be valid closed surfaces, not empty (molsurf.check);\n"
      "the result is one too, or empty (disjoint operands' intersection). Where the operands touch, or\n"
      "their sheets lie closer than rounding to doubles keeps apart, b is moved by a tiny step (2^-36 of\n"
      "the coordinates' scale first) and a UserWarning says so; a result that still fails its check\n"
      "raises molsurf.Error, as `molsurf boolean` refuses it. Face tags of the result are those of the\n"
      "source faces.");

  // ---- Shells of the true spheres ----
  py::class_<molsurf::ShellReport>(m, "Shell",
                                   "One shell of the union of the true spheres (exact, no facets): the outer surface\n"
                                   "or a cavity.")
      .def_property_readonly(
          "kind", [](const molsurf::ShellReport& s) { return s.cavity ? "cavity" : "outer"; },
          "'outer' or 'cavity'.")
      .def_readonly("cavity", &molsurf::ShellReport::cavity, "Whether this is a cavity.")
      .def_readonly("area", &molsurf::ShellReport::area, "Area, A^2 (exact).")
      .def_readonly("volume", &molsurf::ShellReport::volume,
                    "Volume, A^3, unsigned (exact): inside the outer surface, or a cavity's void.")
      .def_property_readonly(
          "centroid",
          [](const molsurf::ShellReport& s) {
            py::array_t<double> out(3);
            double* xyz = out.mutable_data();
            xyz[0] = s.centroid.x;
            xyz[1] = s.centroid.y;
            xyz[2] = s.centroid.z;
            return out;
          },
          "(3,) float64, A: the area-weighted centroid of the shell's surface (copy).")
      .def_property_readonly(
          "atoms",
          [](const molsurf::ShellReport& s) {
            py::array_t<std::int32_t> out(static_cast<py::ssize_t>(s.atoms.size()));
            std::copy(s.atoms.begin(), s.atoms.end(), out.mutable_data());
            return out;
          },
          "(K,) int32: the atoms lining the shell (indices into the structure's atoms), sorted (copy).")
      .def_property_readonly(
          "mesh_component",
          [](const molsurf::ShellReport& s) -> py::object {
            if (s.mesh_component < 0) return py::none();
            return py::int_(s.mesh_component);
          },
          "Index into Surface.components of the (largest) mesh component that follows this shell; None\n"
          "when no mesh component does, or for molsurf.areas() (no mesh).")
      .def(
          "to_dict",
          [](const molsurf::ShellReport& s) {
            py::object mesh_component = py::none();
            if (s.mesh_component >= 0) mesh_component = py::int_(s.mesh_component);
            py::list atoms;
            for (const std::uint32_t a : s.atoms) atoms.append(a);
            return py::dict("kind"_a = s.cavity ? "cavity" : "outer", "area"_a = s.area, "volume"_a = s.volume,
                            "centroid"_a = py::make_tuple(s.centroid.x, s.centroid.y, s.centroid.z),
                            "atoms"_a = atoms, "mesh_component"_a = mesh_component);
          },
          "The shell as a dict, as in the command's JSON report (atoms a list, centroid a tuple).")
      .def("__repr__", [](const molsurf::ShellReport& s) {
        return std::string("<molsurf.Shell ") + (s.cavity ? "cavity" : "outer") + ": area " + std::to_string(s.area) +
               " A^2, volume " + std::to_string(s.volume) + " A^3, " + std::to_string(s.atoms.size()) + " atoms>";
      });

  // ---- Surface ----
  py::class_<PySurface>(m, "Surface",
                        "A solvent-accessible (or, with probe=0, van der Waals) surface: closed, 2-manifold,\n"
                        "outward and checked. Geometry arrays are read-only views of the surface's memory.")
      .def_property_readonly(
          "vertices", [](py::object self) { return vertices_view(self.cast<const PySurface&>().data->computed.mesh, self); },
          "(V, 3) float64 vertex coordinates, A: read-only view.")
      .def_property_readonly(
          "faces", [](py::object self) { return faces_view(self.cast<const PySurface&>().data->computed.mesh, self); },
          "(F, 3) int32 vertex indices, counter-clockwise seen from outside: read-only view.")
      .def_property_readonly(
          "atom_of_face",
          [](py::object self) { return tags_view(self.cast<const PySurface&>().data->computed.mesh, self); },
          "(F,) int32: the index (into structure's atoms) of the atom whose sphere each face lies on:\n"
          "read-only view.")
      .def_property_readonly(
          "ses_patches",
          [](const PySurface& s) -> py::object {
            const auto& m = s.data->computed.ses_patches;
            if (!m) return py::none();
            return py::dict("area"_a = m->area, "volume"_a = m->volume, "contact_area"_a = m->contact_area,
                            "toroidal_area"_a = m->toroidal_area, "reentrant_area"_a = m->reentrant_area,
                            "atom_area"_a = py::array_t<double>(static_cast<py::ssize_t>(m->area_per_atom.size()),
                                                                 m->area_per_atom.data()));
          },
          "The SES only (surface='ses'): its area and volume from the arrangement's patches, beside\n"
          "the facets' (area, volume): a dict with area, volume, contact_area, toroidal_area,\n"
          "reentrant_area and atom_area (N,) per atom; None for the SAS and vdW surfaces.")
      .def_property_readonly(
          "stern",
          [](const PySurface& s) -> py::object {
            if (!s.data->stern) return py::none();
            return py::cast(PySurface{s.data->stern});
          },
          "The Stern layer (surface(..., stern=probe)): the SAS of the same atoms at that probe, a\n"
          "Surface of its own (write() it as the command's --stern writes it); None when not asked for.")
      .def(
          "patches",
          [](const PySurface& s) {
            const SurfaceData& d = *s.data;
            if (!d.computed.ses_arrangement)
              throw Error("patches(): for the solvent-excluded surface (surface='ses') only");
            const molsurf::Mesh& mesh = d.computed.mesh;
            std::vector<molsurf::VertexPatch> labels;
            {
              py::gil_scoped_release release;
              labels = molsurf::ses_vertex_patches(mesh.vertices, d.structure->atoms, d.spheres.probe,
                                                   *d.computed.ses_arrangement);
            }
            const std::vector<molsurf::PatchType> face_types = molsurf::face_patch_types(mesh, labels);
            const std::vector<std::uint32_t> face_numbers = molsurf::face_patch_numbers(mesh, labels);
            const auto n = static_cast<py::ssize_t>(labels.size());
            py::array_t<std::uint8_t> type(n);
            py::array_t<std::int64_t> atom(n);
            py::array_t<double> normal({n, py::ssize_t{3}});
            auto t = type.mutable_unchecked<1>();
            auto a = atom.mutable_unchecked<1>();
            auto u = normal.mutable_unchecked<2>();
            for (py::ssize_t v = 0; v < n; ++v) {
              const molsurf::VertexPatch& l = labels[static_cast<std::size_t>(v)];
              t(v) = static_cast<std::uint8_t>(l.type);
              a(v) = l.atom;
              u(v, 0) = l.normal.x;
              u(v, 1) = l.normal.y;
              u(v, 2) = l.normal.z;
            }
            py::array_t<std::uint8_t> face_type(static_cast<py::ssize_t>(face_types.size()));
            py::array_t<std::int64_t> face_number(static_cast<py::ssize_t>(face_types.size()));
            auto f = face_type.mutable_unchecked<1>();
            auto g = face_number.mutable_unchecked<1>();
            for (py::ssize_t k = 0; k < f.shape(0); ++k) {
              f(k) = static_cast<std::uint8_t>(face_types[static_cast<std::size_t>(k)]);
              g(k) = face_numbers[static_cast<std::size_t>(k)];
            }
            return py::dict("vertex_type"_a = type, "vertex_atom"_a = atom, "vertex_normal"_a = normal,
                            "face_type"_a = face_type, "face_number"_a = face_number);
          },
          "The SES's MSMS patch labels (what its .vert/.face files carry), as NumPy arrays in a dict:\n"
          "vertex_type (V,) uint8 and face_type (F,) uint8, MSMS's numbers (1 toroidal, 2 reentrant,\n"
          "3 contact); vertex_atom (V,) int64, the closest atom (0-based); vertex_normal (V, 3), the\n"
          "analytic outward normal; face_number (F,) int64, the analytical face (0-based: atoms'\n"
          "contact patches first, then the tori of atom pairs, then the probe positions; the .face\n"
          "file's last column is this + 1). Raises molsurf.Error for the SAS and vdW surfaces.")
      .def_property_readonly(
          "mesh",
          [](const PySurface& s) {
            // Shares the surface's memory (aliasing pointer), no copy.
            return PyMesh{std::shared_ptr<const molsurf::Mesh>(s.data, &s.data->computed.mesh)};
          },
          "The surface as a molsurf.Mesh (same memory, tags = atom_of_face).")
      .def_property_readonly(
          "structure", [](const PySurface& s) { return PyStructure{s.data->structure}; },
          "The atoms the surface was computed from (molsurf.Structure).")
      .def_property_readonly(
          "area", [](const PySurface& s) { return s.data->exact.area; },
          "Total area of the true spheres' union, A^2, exact to rounding (not the facets'; see\n"
          "facet_area): the outer surface and the cavities, or with outer_only the outer surface only.\n"
          "For surface='ses' the SES's, from its patches (ses_patches['area']). The command's report 'area'.")
      .def_property_readonly(
          "volume", [](const PySurface& s) { return s.data->exact.volume; },
          "Volume of the true spheres' union, A^3, exact to rounding: inside the outer surface minus the\n"
          "cavities (with outer_only: inside the outer surface); for surface='ses' the SES's, from its\n"
          "patches. The command's report 'volume'.")
      .def_property_readonly(
          "facet_area", [](const PySurface& s) { return s.data->computed.measures.area; },
          "Total area of the mesh's facets, A^2 (all of its components). The report's 'facet_area'.")
      .def_property_readonly(
          "facet_volume", [](const PySurface& s) { return s.data->computed.measures.volume; },
          "Volume enclosed by the facets, A^3: inside the outer surface minus the cavities. The report's\n"
          "'facet_volume'.")
      .def_property_readonly(
          "shells",
          [](const PySurface& s) { return s.data->exact.shells; },
          "The true spheres' shells (list of molsurf.Shell, exact): the outer surface(s) first, then the\n"
          "cavities, each by decreasing area; none of the cavities with outer_only.")
      .def_property_readonly(
          "components", [](const PySurface& s) { return s.data->computed.measures.components; },
          "Connected parts of the mesh (list of Component; the facets' numbers): the largest outer surface\n"
          "first, then by area; cavities have negative volume. shells holds the true spheres' ones.")
      .def_property_readonly(
          "component_shells", [](const PySurface& s) { return component_shells_list(*s.data); },
          "For each of components, the index into shells of the true shell it follows, or None (a mesh\n"
          "cavity that no true cavity explains: a void of the facets).")
      .def_property_readonly(
          "arrangement", [](const PySurface& s) { return arrangement_dict(s.data->exact); },
          "The true spheres' arrangement (dict): vertices, arcs, buried_atoms, exact_decisions,\n"
          "degenerate_points.")
      .def_property_readonly(
          "area_per_atom",
          [](py::object self) {
            const std::vector<double>& area = self.cast<const PySurface&>().data->atom_area;
            return read_only_view(area.data(), {static_cast<py::ssize_t>(area.size())}, self);
          },
          "(N,) float64, A^2: each atom's exposed area on the true spheres (exact; with outer_only only\n"
          "what lies on the outer surface); sums to area. For surface='ses', each atom's share of the\n"
          "SES's patches (its contact patch, and the toroidal and reentrant area nearest its sphere;\n"
          "with outer_only the outer surface's), summing to ses_patches['area'], not to area (the\n"
          "facets'). The --per-atom CSV's area. Read-only view.")
      .def_property_readonly(
          "area_per_residue",
          [](const PySurface& s) { return residue_table(*s.data->structure, s.data->atom_area); },
          "Structured array (copy), one row per residue in order of first appearance, fields chain,\n"
          "residue_name, residue_number, insertion_code ('' when blank), atoms, area (A^2, exact as\n"
          "area_per_atom). The --per-residue CSV.")
      .def_property_readonly(
          "facet_area_per_atom",
          [](py::object self) {
            const std::vector<double>& area = self.cast<const PySurface&>().data->computed.measures.atom_area;
            return read_only_view(area.data(), {static_cast<py::ssize_t>(area.size())}, self);
          },
          "(N,) float64, A^2: area of the mesh faces on each atom's sphere (atom_of_face); sums to\n"
          "facet_area. Read-only view.")
      .def_property_readonly(
          "facet_area_per_residue",
          [](const PySurface& s) { return residue_table(*s.data->structure, s.data->computed.measures.atom_area); },
          "As area_per_residue, from facet_area_per_atom (copy).")
      .def_property_readonly(
          "quality", [](const PySurface& s) { return s.data->computed.quality_after; },
          "Triangle quality of the surface (molsurf.Quality).")
      .def_property_readonly(
          "quality_before_cleanup", [](const PySurface& s) { return s.data->computed.quality_before; },
          "Triangle quality of the union before the cleanup.")
      .def_property_readonly(
          "timings",
          [](const PySurface& s) {
            const molsurf::ComputeSurfaceTimings& t = s.data->computed.seconds;
            return py::dict("union"_a = t.union_, "cleanup"_a = t.cleanup, "check"_a = t.check,
                            "measures"_a = t.measures, "total"_a = t.total);
          },
          "Wall seconds per stage (dict): union, cleanup, check, measures (the facets' measures and the\n"
          "true spheres' arrangement), total.")
      .def_property_readonly(
          "check", [](const PySurface& s) { return s.data->computed.check; }, "The surface's check (molsurf.Check).")
      .def_property_readonly(
          "cleanup",
          [](const PySurface& s) -> py::object {
            if (!s.data->computed.cleanup) return py::none();
            return cleanup_dict(*s.data->computed.cleanup);
          },
          "What the cleanup did (dict), or None with cleanup=False.")
      .def_property_readonly(
          "method", [](const PySurface& s) { return molsurf::surface_method_name(s.data->computed.method); },
          "The method that made the surface: 'one-pass' or 'pairwise'.")
      .def_property_readonly(
          "notes", [](const PySurface& s) { return s.data->computed.notes; },
          "Why the requested method's surface was replaced, one line each (list of str).")
      .def_property_readonly(
          "threads", [](const PySurface& s) { return s.data->computed.threads; }, "Threads used.")
      .def(
          "write",
          [](const PySurface& s, const std::filesystem::path& path, bool ascii, int msms_decimals, bool msms_header) {
            py::gil_scoped_release release;
            return write_surface(*s.data, path, ascii, msms_decimals, msms_header);
          },
          "path"_a, py::kw_only(), "ascii"_a = false, "msms_decimals"_a = 3, "msms_header"_a = true,
          "write(path, *, ascii=False, msms_decimals=3, msms_header=True) -> list of paths\n\n"
          "Writes the surface as the command line does (the same bytes as `molsurf -o path`); the format\n"
          "follows the extension: .vtp .vtk .ply .off .stl .obj .vert (MSMS .vert/.face pair) .msh (gmsh\n"
          "2.2). Cell data carry each face's atom. msms_header=False: numeric rows only, without the header\n"
          "lines and the atom-name column (the command's --no-header, for numpy.loadtxt readers).\n"
          "Lossy formats are checked as they will be held: MSMS decimals are raised (with a warning) where\n"
          "3 would break the surface; an STL that float32 would break raises molsurf.Error. Atomic; returns\n"
          "the files written (list of pathlib.Path).")
      .def("__repr__", [](const PySurface& s) {
        const molsurf::SurfaceMeasures& m = s.data->computed.measures;
        return "<molsurf.Surface: " + std::to_string(m.faces) + " faces, area " + std::to_string(s.data->exact.area) +
               " A^2, volume " + std::to_string(s.data->exact.volume) + " A^3 (true spheres; facets " +
               std::to_string(m.area) + " A^2, " + std::to_string(m.volume) + " A^3)>";
      });

  m.def("surface", &surface_py, "structure"_a = py::none(), py::kw_only(), "centres"_a = py::none(),
        "radii"_a = py::none(), "surface"_a = "sas", "probe"_a = py::none(), "density"_a = 2.0,
        "frequency"_a = py::none(), "method"_a = "one-pass", "cleanup"_a = true, "outer_only"_a = false,
        "area_corrected"_a = true, "check"_a = true, "threads"_a = 0,
        "max_faces"_a = static_cast<long long>(molsurf::kDefaultMaxSphereFaces), "max_memory"_a = py::none(),
        "model"_a = py::none(),
        "chains"_a = py::none(), "keep_water"_a = false, "hydrogens"_a = false, "hetatm"_a = true,
        "radius_set"_a = "protor", "radius_file"_a = py::none(), "progress"_a = py::none(), "stern"_a = py::none(),
        "surface(structure=None, *, centres=None, radii=None, surface='sas', probe=None, density=2.0,\n"
        "        frequency=None,\n"
        "        method='one-pass', cleanup=True, outer_only=False, area_corrected=True, check=True,\n"
        "        threads=0, max_faces=300000000, max_memory=None, model=None, chains=None, keep_water=False,\n"
        "        hydrogens=False, hetatm=True, radius_set='protor', radius_file=None, progress=None,\n"
        "        stern=None) -> Surface\n\n"
        "The surface of a structure, exactly as the molsurf command computes it (same defaults). The\n"
        "structure is a path (str or os.PathLike; read with the selection keywords, as read_structure),\n"
        "a molsurf.Structure, or a gemmi.Structure (no file written; selection keywords apply); or give\n"
        "centres ((N, 3), A) and radii ((N,), A) instead.\n"
        "  surface: 'sas' (solvent accessible, default), 'ses' (solvent excluded: where the rolling probe\n"
        "    touches the atoms; area and volume are then the facets') or 'vdw' (probe 0);\n"
        "  probe: probe radius added to every atom, A (None: 1.4, and 0 for 'vdw', the surface at probe 0;\n"
        "    another probe with 'vdw' is refused, as the command refuses --surface vdw --probe 1.4);\n"
        "  density: icosphere vertices per A^2 of sphere; frequency: fixed icosphere frequency instead;\n"
        "  method: 'one-pass' (default) or 'pairwise' (the reference); cleanup: remove slivers;\n"
        "  outer_only: drop cavities; area_corrected: scale each icosphere to the sphere's area\n"
        "  (False: inscribed); check: run the exact self-intersection test (closedness always is);\n"
        "  threads: 0 for all cores (the result does not depend on it); max_faces: refuse larger jobs;\n"
        "  max_memory: the memory limit in GB (None: this machine's), as --max-memory;\n"
        "  stern: also the Stern layer, the SAS of the same atoms at this probe (A; PyGBe: 2.0), as\n"
        "    --stern-probe: Surface.stern;\n"
        "  progress: a callable, progress(stage, done, total), called on the calling thread as the job\n"
        "    goes (stage 'union', 'cleanup', 'check' or 'measures'; at most 20 times a second); an\n"
        "    exception it raises stops the job and is raised by surface().\n"
        "The GIL is released while it runs; Ctrl-C (KeyboardInterrupt) stops it within a moment.\n"
        "Raises molsurf.Error for bad input, with the command's message (docs/api.md).\n"
        "area, volume, area_per_atom, area_per_residue and shells are the true spheres' (exact, as the\n"
        "command's report and CSV tables); facet_area, facet_volume, facet_area_per_atom and components\n"
        "are the mesh's.");

  // ---- Areas only ----
  py::class_<PyAreas>(m, "Areas",
                      "The exact areas and volumes of the union of the true spheres (r_vdW + probe), with no\n"
                      "mesh: what `molsurf --areas-only` reports. Equal to the same numbers of molsurf.surface()\n"
                      "on the same atoms and probe (the same arrangement).")
      .def_property_readonly(
          "area", [](const PyAreas& a) { return a.data->exact.area; },
          "Total area, A^2: the outer surface and the cavities (with outer_only: the outer surface).")
      .def_property_readonly(
          "volume", [](const PyAreas& a) { return a.data->exact.volume; },
          "Volume, A^3: inside the outer surface minus the cavities (with outer_only: inside the outer\n"
          "surface).")
      .def_property_readonly(
          "area_per_atom",
          [](py::object self) {
            const std::vector<double>& area = self.cast<const PyAreas&>().data->atom_area;
            return read_only_view(area.data(), {static_cast<py::ssize_t>(area.size())}, self);
          },
          "(N,) float64, A^2: each atom's exposed area (with outer_only: on the outer surface only); sums\n"
          "to area. The --per-atom CSV's area. Read-only view.")
      .def_property_readonly(
          "area_per_residue",
          [](const PyAreas& a) { return residue_table(*a.data->structure, a.data->atom_area); },
          "Structured array (copy) as Surface.area_per_residue: chain, residue_name, residue_number,\n"
          "insertion_code, atoms, area (A^2).")
      .def_property_readonly(
          "shells", [](const PyAreas& a) { return a.data->exact.shells; },
          "The shells (list of molsurf.Shell): the outer surface(s) first, then the cavities, each by\n"
          "decreasing area; mesh_component is None (no mesh).")
      .def_property_readonly(
          "structure", [](const PyAreas& a) { return PyStructure{a.data->structure}; },
          "The atoms the areas were computed from (molsurf.Structure).")
      .def_property_readonly(
          "arrangement", [](const PyAreas& a) { return arrangement_dict(a.data->exact); },
          "The arrangement (dict): vertices, arcs, buried_atoms, exact_decisions, degenerate_points.")
      .def_property_readonly(
          "probe", [](const PyAreas& a) { return a.data->probe; }, "The probe radius, A.")
      .def_property_readonly(
          "outer_only", [](const PyAreas& a) { return a.data->outer_only; }, "Whether the cavities are left out.")
      .def_property_readonly(
          "seconds", [](const PyAreas& a) { return a.data->exact.seconds; }, "Wall seconds of the arrangement.")
      .def_property_readonly(
          "threads", [](const PyAreas& a) { return a.data->threads; }, "Threads used.")
      .def("__repr__", [](const PyAreas& a) {
        std::size_t cavities = 0;
        for (const molsurf::ShellReport& s : a.data->exact.shells) cavities += s.cavity;
        return "<molsurf.Areas: " + std::to_string(a.data->structure->atoms.size()) + " atoms, area " +
               std::to_string(a.data->exact.area) + " A^2, volume " + std::to_string(a.data->exact.volume) + " A^3, " +
               std::to_string(cavities) + " cavit" + (cavities == 1 ? "y" : "ies") + ">";
      });

  py::class_<PyTrajectoryAreas>(
      m, "TrajectoryAreas",
      "The exact areas and volumes of the true spheres (r_vdW + probe) of every frame of a trajectory:\n"
      "areas() with coordinates of shape (frames, atoms, 3). Frame k's numbers are the same doubles as\n"
      "areas(centres=coords[k], radii=radii, probe=probe) gives.")
      .def_property_readonly(
          "area_per_atom",
          [](py::object self) {
            const TrajectoryAreasData& d = *self.cast<const PyTrajectoryAreas&>().data;
            return read_only_view(d.area_per_atom.data(),
                                  {static_cast<py::ssize_t>(d.frames), static_cast<py::ssize_t>(d.atoms)}, self);
          },
          "(frames, atoms) float64, A^2: each atom's exposed area in each frame (with outer_only: on the\n"
          "outer surface only); each row sums to that frame's area. Read-only view.")
      .def_property_readonly(
          "area",
          [](py::object self) {
            const TrajectoryAreasData& d = *self.cast<const PyTrajectoryAreas&>().data;
            return read_only_view(d.area.data(), {static_cast<py::ssize_t>(d.frames)}, self);
          },
          "(frames,) float64, A^2: each frame's total area (with outer_only: the outer surface's).")
      .def_property_readonly(
          "volume",
          [](py::object self) {
            const TrajectoryAreasData& d = *self.cast<const PyTrajectoryAreas&>().data;
            return read_only_view(d.volume.data(), {static_cast<py::ssize_t>(d.frames)}, self);
          },
          "(frames,) float64, A^3: each frame's volume, inside the outer surface minus the cavities\n"
          "(with outer_only: inside the outer surface).")
      .def_property_readonly(
          "radii",
          [](py::object self) {
            const TrajectoryAreasData& d = *self.cast<const PyTrajectoryAreas&>().data;
            return read_only_view(d.radii.data(), {static_cast<py::ssize_t>(d.atoms)}, self);
          },
          "(atoms,) float64, A: the radii as given (without the probe).")
      .def_property_readonly(
          "frames", [](const PyTrajectoryAreas& t) { return t.data->frames; }, "Number of frames.")
      .def_property_readonly(
          "atoms", [](const PyTrajectoryAreas& t) { return t.data->atoms; }, "Number of atoms.")
      .def("__len__", [](const PyTrajectoryAreas& t) { return t.data->frames; })
      .def_property_readonly(
          "probe", [](const PyTrajectoryAreas& t) { return t.data->probe; }, "The probe radius, A.")
      .def_property_readonly(
          "outer_only", [](const PyTrajectoryAreas& t) { return t.data->outer_only; },
          "Whether the cavities are left out.")
      .def_property_readonly(
          "seconds", [](const PyTrajectoryAreas& t) { return t.data->seconds; }, "Wall seconds of all the frames.")
      .def_property_readonly(
          "threads", [](const PyTrajectoryAreas& t) { return t.data->threads; },
          "Threads used (frames run in parallel, one thread each).")
      .def("__repr__", [](const PyTrajectoryAreas& t) {
        return "<molsurf.TrajectoryAreas: " + std::to_string(t.data->frames) + " frames, " +
               std::to_string(t.data->atoms) + " atoms>";
      });

  m.def("areas", &areas_py, "structure"_a = py::none(), py::kw_only(), "centres"_a = py::none(),
        "coords"_a = py::none(), "radii"_a = py::none(), "probe"_a = 1.4, "outer_only"_a = false, "threads"_a = 0,
        "model"_a = py::none(), "chains"_a = py::none(), "keep_water"_a = false, "hydrogens"_a = false,
        "hetatm"_a = true, "radius_set"_a = "protor", "radius_file"_a = py::none(),
        "areas(structure=None, *, centres=None, coords=None, radii=None, probe=1.4, outer_only=False,\n"
        "      threads=0, model=None, chains=None, keep_water=False, hydrogens=False, hetatm=True,\n"
        "      radius_set='protor', radius_file=None) -> Areas or TrajectoryAreas\n\n"
        "The exact solvent-accessible (probe=0: van der Waals) areas and volumes of the true spheres,\n"
        "with no mesh: `molsurf --areas-only`. The structure is given as to surface(): a path, a\n"
        "molsurf.Structure or a gemmi.Structure (selection keywords as read_structure), or centres\n"
        "((N, 3), A) and radii ((N,), A, without the probe; finite, >= 0). coords is another name for\n"
        "centres, and a NumPy array as the first argument is taken as coordinates too.\n"
        "Coordinates of shape (frames, atoms, 3) with radii of shape (atoms,) give a TrajectoryAreas:\n"
        "area_per_atom (frames, atoms), area and volume (frames,), frame k the same doubles as a call on\n"
        "coords[k]; the frames run in parallel, each on one thread.\n"
        "  probe: added to every radius, A; outer_only: leave the cavities out;\n"
        "  threads: 0 for all cores (the result does not depend on it).\n"
        "The same numbers as surface(...).area, volume, area_per_atom and shells for the same atoms and\n"
        "probe. The GIL is released while it runs (Ctrl-C is seen when it returns). Raises\n"
        "molsurf.Error for bad input.");
}
