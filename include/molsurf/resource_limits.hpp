#pragma once
// What a surface will cost, known before any sphere is built, and the limit that keeps a
// typo (--density 1e6, --probe 3e4, a 1000 A radius) from running the machine out of
// memory: the estimate is refused plainly, and a flag raises the limit.
#include <cstdint>
#include <filesystem>
#include <span>

#include "molsurf/atoms.hpp"
#include "molsurf/surface.hpp"

namespace molsurf {

// Peak memory per sphere face before the union, measured on the capsid (1f2n, 253 M
// sphere faces at density 4: 6 GB at probe 1.4, 18.7 GB at probe 0; docs/performance.md),
// rounded up.
inline constexpr std::uint64_t kBytesPerSphereFace = 80;
// Default --max-faces: above the largest documented run (the capsid at density 4).
inline constexpr std::uint64_t kDefaultMaxSphereFaces = 300'000'000;
// No sphere may be finer than --frequency allows (n = 200: 800 000 faces). At density 2
// an atom gets n = 5 to 8; a sphere beyond this is a unit or radius error (a 1000 A
// radius at density 2 has 50 M faces and ran out of 24 GB on its own), not a surface
// anyone needs.
inline constexpr std::uint64_t kMaxFacesPerSphere = 20 * 200 * 200;

// The whole job's peak memory (union, cleanup, check, write) per face of the union before
// cleanup, as resident memory over those faces in `molsurf`, which returns freed memory at
// once on jobs this large: 2btv at probe 0, density 4 (22.9 M faces, 3.19 GB) gives 139
// bytes, the capsid at the defaults (11.5 M faces, 1.88 GB) 164 (docs/performance.md,
// "Memory"); rounded up.
inline constexpr std::uint64_t kBytesPerSurfaceFace = 180;

// Peak memory of a structure read per byte of its text: the text, gemmi's document and
// the structure built from it, all held at once. Measured on the capsid's mmCIF (24 MB of
// text, about 15 bytes per byte; a PDB file takes less), rounded up. Text beyond the
// memory limit over this is refused before it is read (ReadOptions::max_memory).
inline constexpr std::uint64_t kBytesPerTextByte = 16;

// The memory this process may use: the machine's physical memory, or its control group's
// limit (cgroup v2 memory.max) when that is lower.
std::uint64_t available_memory_bytes();

// Throws molsurf::Error naming `input` when the estimate exceeds `max_bytes` (the message
// gives the faces, the memory, and the flags that lower the size or raise the limit).
void check_surface_memory(const std::filesystem::path& input, const SurfaceSizeEstimate& estimate,
                          std::uint64_t max_bytes);

struct ResourceEstimate {
  std::uint64_t sphere_faces = 0;    // all icospheres' faces, saturating (never wraps)
  std::uint64_t largest_sphere = 0;  // faces of the largest one
  std::uint64_t bytes = 0;           // peak memory estimate, saturating
};

// Overflow-safe: a frequency too large for an int is estimated in floating point.
ResourceEstimate estimate_resources(std::span<const Atom> atoms, const SphereOptions& options);
// The same from the atoms' radii alone (without the probe): what a caller holding arrays
// can ask before it builds any atom.
ResourceEstimate estimate_resources(std::span<const double> radii, const SphereOptions& options);

// No sphere (radius + probe) below this is triangulated: its icosphere's corners would
// round onto each other (a radius of 1e-310 gave degenerate faces deep in the union).
inline constexpr double kMinSphereRadius = 1e-6;

// Throws molsurf::Error naming `input` when `estimate` has a sphere finer than
// kMaxFacesPerSphere or more than `max_faces` faces in all (check_sphere_resources' limits).
void check_sphere_faces(const std::filesystem::path& input, const ResourceEstimate& estimate,
                        const SphereOptions& options, std::uint64_t max_faces);

// Throws molsurf::Error naming `input` unless every sphere can be built: radius + probe
// finite and at least kMinSphereRadius (a zero-radius atom with --probe 0 is named with its serial and
// residue), the sphere's faces within kMaxFacesPerSphere, and all spheres' faces within
// `max_faces` (the message gives the estimate, the memory, and the flag that raises it).
void check_sphere_resources(const std::filesystem::path& input, std::span<const Atom> atoms,
                            const SphereOptions& options, std::uint64_t max_faces);

}  // namespace molsurf
