#include "blocks/streamed_surface.hpp"

#include <algorithm>
#include <bit>
#include <chrono>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <unordered_map>
#include <utility>

#include "blocks/band_reach.hpp"
#include "blocks/block_areas.hpp"
#include "blocks/block_piece.hpp"
#include "blocks/first_process_verdict.hpp"
#include "blocks/piece_job.hpp"
#include "blocks/seam.hpp"
#include "blocks/pieces_of_all_blocks.hpp"
#include "blocks/streamed_piece.hpp"
#include "mesh/component_volume.hpp"
#include "mesh/topology.hpp"
#include "molsurf/error.hpp"
#include "molsurf/mesh_check.hpp"
#include "molsurf/surface_measures.hpp"
#include "surface/cleanup.hpp"

namespace molsurf::blocks {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

struct PointKey {
  std::array<std::uint64_t, 3> bits;
  bool operator==(const PointKey&) const = default;
};

struct PointHash {
  std::size_t operator()(const PointKey& k) const {
    std::uint64_t h = 0x9e3779b97f4a7c15ull;
    for (std::uint64_t b : k.bits) h = (h ^ b) * 0xff51afd7ed558ccdull, h ^= h >> 33;
    return static_cast<std::size_t>(h);
  }
};

PointKey key_of(const Vec3& p) {
  return {std::bit_cast<std::uint64_t>(p.x + 0.0), std::bit_cast<std::uint64_t>(p.y + 0.0),
          std::bit_cast<std::uint64_t>(p.z + 0.0)};
}

std::uint32_t root_of(std::vector<std::uint32_t>& parent, std::uint32_t x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

// The seams' bands glued, and after them every piece's border, on vertices of its own and
// tagged -2 - atom; with cleanup, cleaned with both sides in view: everything beyond
// kSeamCleanupBand rings of the seams frozen, the borders too, so no edit crosses a written
// face. The pieces' bands and borders are released as they are taken: the join holds each
// face once.
struct SeamsAndBorders {
  Mesh mesh;
  std::size_t band_faces = 0, band_vertices = 0;
  std::optional<BandVertices> band;  // the glued band's vertices before cleanup
};

SeamsAndBorders joined_seams(std::span<const Atom> atoms, const ComputeSurfaceOptions& options,
                             const BlockPartition& partition, std::vector<StreamedPiece>& pieces,
                             ComputedSurface& result) {
  std::vector<Mesh> bands;
  std::vector<std::vector<SeamPoint>> seams;
  for (StreamedPiece& p : pieces) {
    bands.push_back(std::move(p.band));
    seams.push_back(std::move(p.seam));
  }
  std::vector<std::uint8_t> on_seam;
  SeamsAndBorders out;
  Mesh& glued = out.mesh;
  glued = glue_pieces(bands, seams, exact_same_point(atoms, options.spheres, partition.contained), &on_seam);
  bands = {};
  seams = {};
  out.band_faces = glued.faces.size();
  out.band_vertices = glued.vertices.size();
  {
    std::vector<std::uint32_t> block_of_face(glued.faces.size());
    for (std::size_t f = 0; f < glued.faces.size(); ++f)
      block_of_face[f] = partition.block_of[static_cast<std::size_t>(glued.tag(f))];
    out.band.emplace(glued, block_of_face, band_reach(options.spheres));
  }
  const bool clean = options.cleanup && out.band_faces > 0;
  std::vector<std::uint8_t> frozen;
  if (clean) frozen = frozen_beyond(glued, on_seam, kSeamCleanupBand);
  on_seam = {};
  std::size_t faces = out.band_faces, vertices = out.band_vertices;
  for (const StreamedPiece& p : pieces) faces += p.border.faces.size(), vertices += p.border.vertices.size();
  glued.faces.reserve(faces);
  glued.face_tags.reserve(faces);
  glued.vertices.reserve(vertices);
  for (StreamedPiece& p : pieces) {
    glued.append(p.border);
    p.border = Mesh{};
  }
  // The borders' faces are told apart by their tags: none of them can change, as every
  // vertex they have is frozen and no edge of theirs is shared with a band face.
  for (std::size_t f = out.band_faces; f < glued.faces.size(); ++f) glued.face_tags[f] = -2 - glued.face_tags[f];
  if (!clean) return out;
  const auto clock = Clock::now();
  frozen.resize(glued.vertices.size(), 1);
  CleanupOptions cleanup = options.cleanup_options;
  cleanup.measure_after = false;
  add_cleanup(result, improve_surface(glued, cleanup, frozen));
  result.seconds.cleanup += seconds_since(clock);
  return out;
}

// The seams alone: the band's faces (in order, on their vertices in order of first use once
// cleaned, as they were glued otherwise).
Mesh seams_of(const SeamsAndBorders& joined, bool cleaned) {
  const Mesh& m = joined.mesh;
  Mesh seams;
  if (!cleaned) {
    seams.vertices.assign(m.vertices.begin(), m.vertices.begin() + static_cast<std::ptrdiff_t>(joined.band_vertices));
    seams.faces.assign(m.faces.begin(), m.faces.begin() + static_cast<std::ptrdiff_t>(joined.band_faces));
    seams.face_tags.assign(m.face_tags.begin(), m.face_tags.begin() + static_cast<std::ptrdiff_t>(joined.band_faces));
    return seams;
  }
  return faces_where(m, [&](std::size_t f) { return m.face_tags[f] >= 0; });
}

// The cleaned seams and every border as one mesh, glued where their vertices lie at the same
// exact position: each border vertex becomes the seams' vertex there, or the first border
// vertex there. Vertices of the seams are never merged with one another (two at one place
// are a contact the check must see). Tags become atoms again; unused vertices go.
Mesh seams_with_borders(SeamsAndBorders&& joined) {
  Mesh m = std::move(joined.mesh);
  enum : std::uint8_t { unused = 0, seam = 1, border = 2 };
  std::vector<std::uint8_t> role(m.vertices.size(), unused);
  for (std::size_t f = 0; f < m.faces.size(); ++f)
    for (Index v : m.faces[f]) role[v] |= m.face_tags[f] >= 0 ? seam : border;
  struct Entry {
    PointKey key;
    bool border;
    Index vertex;
    auto order() const { return std::tie(key.bits, border, vertex); }
  };
  std::vector<Entry> entries;
  for (Index v = 0; v < m.vertices.size(); ++v)
    if (role[v] != unused) entries.push_back({key_of(m.vertices[v]), !(role[v] & seam), v});
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.order() < b.order(); });
  std::vector<Index> vertex_of(m.vertices.size());
  std::iota(vertex_of.begin(), vertex_of.end(), Index{0});
  for (std::size_t i = 0, first = 0; i < entries.size(); ++i) {
    if (entries[i].key != entries[first].key) first = i;
    if (entries[i].border) vertex_of[entries[i].vertex] = entries[first].vertex;
  }
  entries = {};
  role = {};
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    if (m.face_tags[f] >= 0) continue;
    m.face_tags[f] = -2 - m.face_tags[f];
    for (Index& v : m.faces[f]) v = vertex_of[v];
  }
  vertex_of = {};
  drop_unused_vertices(m);
  return m;
}

// Every seam face within band_reach of its own block's band as the pieces left it, so that
// the borders hold every written face it could cross or touch (band_reach.hpp).
void check_band_drift(const Mesh& seams, const BandVertices& band, const BlockPartition& partition,
                      const SphereOptions& spheres) {
  double drift = 0;
  for (std::size_t f = 0; f < seams.faces.size(); ++f)
    drift = std::max(drift, band.drift(seams, f, partition.block_of[static_cast<std::size_t>(seams.tag(f))]));
  if (const double reach = band_reach(spheres); drift > reach)
    throw Error("--blocks: a face of the seams lies " + std::to_string(drift) +
                " A from the seam band it was cleaned from, beyond the " + std::to_string(reach) +
                " A the check of the seams covers; write one file (--merge)");
}

// The cleaned seams and every border glued (seams_with_borders), checked as a piece is: its
// only boundary where the borders meet written faces left out.
void check_seams(const Mesh& seams, Mesh&& together, std::span<const StreamedPiece> pieces,
                 const ComputeSurfaceOptions& options, std::span<const Atom> atoms, const BlockPartition& partition) {
  const HeldAtoms whole{atoms, {}, partition.block_of, partition.contained};
  std::uint64_t open_edges = 0;
  double stray = 0;
  for (const StreamedPiece& p : pieces) {
    open_edges += p.border_open_edges;
    stray = std::max(stray, p.stray);
  }
  for (std::size_t f = 0; f < seams.faces.size(); ++f) stray = std::max(stray, stray_of(seams, f, whole, options.spheres));
  if (const double reach = border_reach(options.spheres); stray > reach)
    throw Error("--blocks: a face lies " + std::to_string(stray) + " A outside its atom's sphere, beyond the " +
                std::to_string(reach) + " A the check of the seams covers; write one file (--merge)");
  const MeshCheck check = check_mesh(together, check_options_of(options));
  if (const auto problems = piece_problems(check, open_edges); !problems.empty()) {
    std::string text = "the seams between the blocks, with the faces near them, have";
    for (const std::string& p : problems) text += " " + p + ";";
    throw SurfaceCheckFailed(check, std::move(together), {text});
  }
}

// The surface's measures from the pieces' summaries and the seams: totals, per-atom areas,
// and the components, each piece's written parts joined through the seams' faces.
void merge_measures(const Mesh& seams, std::span<const StreamedPiece> pieces, std::size_t atom_count,
                    const Vec3& origin, const SphereArrangement* exact, ComputedSurface& result) {
  SurfaceMeasures& m = result.measures;
  m.atom_area.assign(atom_count, 0);
  const Components band = connected_components(seams);
  std::size_t parts = band.count;
  for (const StreamedPiece& p : pieces) parts += p.parts.size();
  std::vector<std::uint32_t> parent(parts);
  std::iota(parent.begin(), parent.end(), 0u);
  std::vector<ComponentMeasure> node(parts);
  std::vector<std::vector<std::uint32_t>> atoms_of(parts);
  std::vector<std::uint32_t> vertex_part(seams.vertices.size(), 0);
  for (std::size_t f = 0; f < seams.faces.size(); ++f) {
    const std::uint32_t c = band.face_component[f];
    const double area = face_area(seams, f);
    ComponentMeasure& n = node[c];
    ++n.faces;
    n.area += area;
    n.volume += six_volume_about(seams, f, origin) / 6;
    atoms_of[c].push_back(static_cast<std::uint32_t>(seams.tag(f)));
    m.atom_area[static_cast<std::size_t>(seams.tag(f))] += area;
    for (Index v : seams.faces[f]) vertex_part[v] = c;
  }
  std::unordered_map<PointKey, std::uint32_t, PointHash> part_at;
  for (Index v = 0; v < seams.vertices.size(); ++v) part_at.emplace(key_of(seams.vertices[v]), vertex_part[v]);
  m.faces = seams.faces.size();
  m.vertices = seams.vertices.size();
  m.quality = mesh_quality(seams);
  std::uint32_t next = static_cast<std::uint32_t>(band.count);
  for (const StreamedPiece& p : pieces) {
    m.faces += p.faces;
    m.vertices += p.vertices;
    combine_quality(m.quality, p.quality);
    for (const AtomArea& a : p.atom_area) m.atom_area[a.atom] += a.area;
    for (const WrittenPart& part : p.parts) {
      const std::uint32_t k = next++;
      node[k] = {part.faces, part.area, part.volume};
      atoms_of[k] = part.atoms;
      for (const Vec3& joint : part.joints) {
        const auto it = part_at.find(key_of(joint));
        if (it == part_at.end()) throw std::logic_error("compute_streamed_surface: a written face left the seams");
        const std::uint32_t a = root_of(parent, k), b = root_of(parent, it->second);
        if (a != b) parent[std::max(a, b)] = std::min(a, b);
      }
    }
  }
  // A band component that no written part joins is closed on its own: its volume about its
  // own vertex with an exact sign, as a part's (streamed_piece.cpp) and one process's.
  const ComponentVolumes band_own = component_volumes(seams, band);
  std::vector<std::uint32_t> nodes_of_root(parts, 0);
  for (std::uint32_t k = 0; k < parts; ++k) ++nodes_of_root[root_of(parent, k)];
  for (std::uint32_t k = 0; k < band.count; ++k)
    if (nodes_of_root[root_of(parent, k)] == 1) node[k].volume = band_own.volume[k];
  // Components in order of their first part, then reported as measure_components orders them.
  std::vector<std::int64_t> component_of_root(parts, -1);
  std::vector<ComponentMeasure> components;
  std::vector<std::vector<std::uint32_t>> component_atoms;
  for (std::uint32_t k = 0; k < parts; ++k) {
    const std::uint32_t r = root_of(parent, k);
    if (component_of_root[r] < 0) {
      component_of_root[r] = static_cast<std::int64_t>(components.size());
      components.emplace_back();
      component_atoms.emplace_back();
    }
    const auto c = static_cast<std::size_t>(component_of_root[r]);
    components[c].faces += node[k].faces;
    components[c].area += node[k].area;
    components[c].volume += node[k].volume;
    component_atoms[c].insert(component_atoms[c].end(), atoms_of[k].begin(), atoms_of[k].end());
  }
  std::vector<std::size_t> order(components.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
    const ComponentMeasure &a = components[x], &b = components[y];
    if (a.cavity() != b.cavity()) return !a.cavity();
    return a.area > b.area;
  });
  std::vector<std::vector<std::uint32_t>> atoms_in_order;
  for (std::size_t c : order) {
    m.components.push_back(components[c]);
    m.area += components[c].area;
    m.volume += components[c].volume;
    atoms_in_order.push_back(std::move(component_atoms[c]));
  }
  if (exact) result.component_shells = shells_of_atom_sets(atoms_in_order, *exact);

  // The whole surface's check, as its parts passed theirs: every piece but for its seam and
  // band, the seams with the borders near them.
  MeshCheck& check = result.check;
  check.faces = m.faces;
  check.vertices = m.vertices;
  check.edges = 3 * m.faces / 2;
  check.components = m.components.size();
  check.euler_characteristic =
      static_cast<long>(check.vertices) - static_cast<long>(check.edges) + static_cast<long>(check.faces);
  check.area = m.area;
  check.volume = m.volume;
  check.quality = m.quality;
}

}  // namespace

BlockedSurface compute_streamed_surface(std::span<const Atom> atoms, const BlockPartition* partition,
                                        const HeldBlocks& held, const Vec3& origin,
                                        const ComputeSurfaceOptions& options, const BlockedSurfaceOptions& blocked) {
  const auto start = Clock::now();
  BlockedSurface out;
  ComputedSurface& result = out.surface;
  result.threads = options.threads;
  auto report = [&](SurfaceStage stage, std::size_t done, std::size_t total) {
    throw_if_cancelled(options.cancel);
    if (options.progress) options.progress(stage, done, total);
  };
  // One block's piece: made, its written faces handed out and released, the rest kept.
  auto make = [&](std::size_t b) {
    SplitPiece split = split_piece(make_piece(held, b, options, result.threads), held.held(), options.spheres, origin);
    if (blocked.piece_done) blocked.piece_done(b, split.written);
    // Released before the block's exact areas, so that the two never add up.
    split.written = Mesh{};
    if (options.exact_areas) {
      const auto clock = Clock::now();
      split.kept.exact = block_arrangement(held.block_atoms(b), options.spheres, result.threads);
      split.kept.seconds_exact = seconds_since(clock);
    }
    return std::move(split.kept);
  };

  const std::size_t blocks = held.block_count();
  report(SurfaceStage::union_, 0, blocks);
  BlockExchange* exchange = blocked.exchange;
  const bool shared = exchange != nullptr && exchange->size() > 1;
  // Each process writes its own pieces and sends the first what it kept (or what went
  // wrong); the first tells every process whether the whole surface passed, and only then
  // may they keep their files.
  std::optional<std::vector<StreamedPiece>> made;
  try {
    made = pieces_of_all_blocks<StreamedPiece>(
        blocks, exchange, make, append_streamed_piece,
        [](std::string_view bytes) { return read_streamed_pieces(bytes); },
        [&](std::size_t done) { report(SurfaceStage::union_, done, blocks); }, /*on_disk=*/true);
  } catch (const std::exception& e) {
    if (shared && exchange->rank() == 0) exchange->broadcast(e.what());
    throw;
  }
  if (!made) {
    const std::string verdict = exchange->broadcast({});
    if (!verdict.empty()) throw FirstProcessVerdict(verdict);
    out.root = false;
    return out;
  }
  std::vector<StreamedPiece>& pieces = *made;
  try {
    if (partition == nullptr || atoms.size() != held.total_atoms())
      throw std::logic_error("compute_streamed_surface: the first process without the whole structure");
    if (pieces.size() != blocks) throw std::logic_error("compute_streamed_surface: a block without its piece");
    Quality before;
    for (const StreamedPiece& p : pieces) {
      add_piece_totals(result, before, p, options.cleanup);
      BlockStats stats = p.stats;
      stats.faces = p.faces;
      out.blocks.push_back(stats);
    }
    report(SurfaceStage::check, 0, 1);
    SeamsAndBorders joined = joined_seams(atoms, options, *partition, pieces, result);
    const Mesh seams = seams_of(joined, options.cleanup && joined.band_faces > 0);
    check_band_drift(seams, *joined.band, *partition, options.spheres);
    joined.band.reset();
    auto clock = Clock::now();
    check_seams(seams, seams_with_borders(std::move(joined)), pieces, options, atoms, *partition);
    result.seconds.check += seconds_since(clock);
    report(SurfaceStage::check, 1, 1);

    clock = Clock::now();
    report(SurfaceStage::measures, 0, 1);
    if (options.exact_areas) {
      std::vector<arrangement::ArrangementPart> parts;
      for (StreamedPiece& p : pieces) parts.push_back(std::move(p.exact));
      result.exact = joined_block_areas(atoms, options.spheres, parts);
    }
    merge_measures(seams, pieces, atoms.size(), origin, options.exact_areas ? &result.exact : nullptr, result);
    result.check.self_intersections_checked = options.check_self_intersections;
    result.seconds.measures = seconds_since(clock);
    for (const StreamedPiece& p : pieces) result.seconds.measures += p.seconds_exact;
    report(SurfaceStage::measures, 1, 1);
    if (result.cleanup) {
      result.cleanup->before = before;
      result.cleanup->after = result.check.quality;
      result.cleanup->area_after = result.check.area;
    }
    result.quality_before = before;
    result.quality_after = result.check.quality;
    if (blocked.seams_done) blocked.seams_done(seams);
  } catch (const std::exception& e) {
    if (shared) exchange->broadcast(e.what());
    throw;
  }
  if (shared) exchange->broadcast({});
  result.method = SurfaceMethod::one_pass;
  result.seconds.total = seconds_since(start);
  return out;
}

}  // namespace molsurf::blocks
