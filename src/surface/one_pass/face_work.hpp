#pragma once
// What the trim of one face builds: its points (implicit, each with its definition and
// where it lies on the face), the traces of the neighbours' faces on it, and the buffers
// of the split, reused from face to face so that the steady state allocates nothing.
#include <array>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include "boolean/ear_clipping.hpp"
#include "boolean/face_points.hpp"
#include "boolean/intersect.hpp"
#include "geometry/implicit_point.hpp"
#include "surface/atom_polyhedra.hpp"
#include "surface/one_pass/point_definition.hpp"

namespace molsurf::surface_detail::one_pass {

// Points are merged by definition (PointDefinition: the same input elements name the same
// point), so the faces and atoms that meet at a point find it without arithmetic. Points
// that are equal with different definitions (degenerate contacts) are merged after the
// join by exact value.
struct DefinitionHash {
  std::size_t operator()(const PointDefinition& d) const { return static_cast<std::size_t>(d.hash()); }
};

// How a neighbour's lens meets the face's plane: across it, or lying in it with the same
// or the opposite orientation (the tie rule of classify decides the shared part).
enum class Plane : std::uint8_t { cuts, coplanar_same, coplanar_opposite };

// Where a point lies on the face being trimmed: corner k, inside edge k (corner k to
// k + 1), or in the interior.
using Place = boolean_engine::Location;

struct Segment {
  std::uint32_t s = 0, t = 0;  // local point ids
  std::uint32_t neighbour = 0;  // index into the atom's neighbour list
  std::uint32_t plane = 0;      // the neighbour's face whose plane holds it
  std::vector<std::uint32_t> crossings;  // points where other traces cross it
};

// Everything one face's trimming builds, reused from face to face (no allocation in the
// steady state).
struct FaceWork {
  std::vector<geometry::ImplicitPoint> points;
  std::vector<PointDefinition> definitions;  // of points
  std::vector<Place> places;
  // Per point: neighbours whose boundary holds it. Longer than `points` when an earlier face
  // had more: the lists are emptied and reused, not freed (one allocation per point else).
  std::vector<std::vector<std::uint32_t>> on_neighbour;
  std::vector<Segment> segments;
  std::vector<std::uint32_t> near;   // neighbours whose boxes meet the face's
  std::vector<std::uint32_t> relevant;
  std::vector<Plane> plane_kind;     // per neighbour (valid for relevant ones)
  // Buffers of split and classify.
  std::vector<std::uint32_t> scratch;
  std::vector<std::uint8_t> on_segment;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> unique_segments;
  std::vector<std::vector<std::uint32_t>> unique_crossings;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::int8_t> inside;
  boolean_engine::FaceToSplit face;
  boolean_engine::PolylineWork polylines;
  // The points on the trimmed atom's own edges, built once: each edge is shared by two of
  // its faces, which meet the same neighbour faces there. Emptied per atom.
  std::uint32_t atom = 0;
  std::unordered_map<PointDefinition, geometry::ImplicitPoint, DefinitionHash> own_edge_points;

  void clear() {
    points.clear();
    definitions.clear();
    places.clear();
    segments.clear();
    near.clear();
    relevant.clear();
  }

  const geometry::ImplicitPoint& own_edge_point(const PointDefinition& d, const AtomPolyhedra& polyhedra);

  // The id of the point d defines, merged with an equal point already there; `neighbour`
  // (~0: none) is a neighbour whose boundary holds it.
  std::uint32_t add(const PointDefinition& d, const AtomPolyhedra& polyhedra, Place place, std::uint32_t neighbour);
};

}  // namespace molsurf::surface_detail::one_pass
