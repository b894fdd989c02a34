#include "blocks/block_share.hpp"

#include <algorithm>
#include <stdexcept>

#include "blocks/byte_stream.hpp"
#include "blocks/first_process_verdict.hpp"
#include "blocks/piece_job.hpp"
#include "blocks/streamed_piece.hpp"
#include "geometry/point_grid.hpp"
#include "molsurf/mesh.hpp"
#include "molsurf/surface.hpp"

namespace molsurf::blocks {

namespace {

void put_string(std::string& out, const std::string& text) {
  put(out, static_cast<std::uint64_t>(text.size()));
  out += text;
}

std::string get_string(ByteReader& in) {
  const std::vector<char> chars = in.get_array<char>();  // the same length check as every array
  return std::string(chars.begin(), chars.end());
}

// Every field of the record: the pieces' files name residues and chains, and the spheres'
// radii and classes come from it.
void put_atom(std::string& out, const Atom& a) {
  put(out, a.centre);
  put(out, a.radius);
  put_string(out, a.element);
  put_string(out, a.atom_name);
  put_string(out, a.residue_name);
  put(out, a.residue_number);
  put(out, a.insertion_code);
  put_string(out, a.chain);
  put(out, a.serial);
  put(out, a.occupancy);
  put(out, a.b_factor);
  put(out, a.charge);
  put(out, a.hetero);
  put(out, a.polarity);
}

Atom get_atom(ByteReader& in) {
  Atom a;
  a.centre = in.get<Vec3>();
  a.radius = in.get<double>();
  a.element = get_string(in);
  a.atom_name = get_string(in);
  a.residue_name = get_string(in);
  a.residue_number = in.get<std::int64_t>();
  a.insertion_code = in.get<char>();
  a.chain = get_string(in);
  a.serial = in.get<int>();
  a.occupancy = in.get<double>();
  a.b_factor = in.get<double>();
  a.charge = in.get<double>();
  a.hetero = in.get<bool>();
  a.polarity = in.get<Polarity>();
  return a;
}

}  // namespace

BlockShare share_of_process(std::span<const Atom> atoms, const BlockPartition& partition, const SphereOptions& spheres,
                            int rank, int size) {
  if (rank < 0 || size < 1 || rank >= size) throw std::invalid_argument("share_of_process: no such process");
  const std::size_t n = atoms.size();
  BlockShare share;
  share.block_count = partition.size();
  share.total_atoms = n;
  share.origin = volume_origin(atoms);
  for (std::size_t b = static_cast<std::size_t>(rank); b < partition.size(); b += static_cast<std::size_t>(size))
    share.blocks.push_back(b);

  // Every atom this process needs, marked; the near atoms found through a grid of cells as
  // wide as two of the largest grown boxes, so that any two boxes that meet are in
  // neighbouring cells.
  const double reach = border_reach(spheres) + 0.5;
  std::vector<std::uint8_t> needed(n, 0);
  std::vector<Vec3> centres(n);
  double largest = 0;
  for (std::size_t i = 0; i < n; ++i) {
    centres[i] = atoms[i].centre;
    largest = std::max(largest, sphere_radius(atoms[i], spheres));
  }
  const geometry::PointGrid grid(centres, 2 * (largest + reach));
  for (std::size_t b : share.blocks) {
    for (std::uint32_t i : partition.atoms[b]) {
      needed[i] = 1;
      const BoundingBox box = sphere_box(atoms[i], spheres, reach);
      grid.for_each_near(centres[i], [&](std::uint32_t j) {
        if (!needed[j] && partition.block_of[j] != b && sphere_box(atoms[j], spheres, reach).overlaps(box))
          needed[j] = 1;
      });
    }
    for (std::uint32_t j : partition.halo[b]) needed[j] = 1;
  }
  std::vector<std::uint32_t> position(n, 0);
  for (std::uint32_t i = 0; i < n; ++i) {
    if (!needed[i]) continue;
    position[i] = static_cast<std::uint32_t>(share.atoms.size());
    share.atoms.push_back(atoms[i]);
    share.global_index.push_back(i);
    share.block_of.push_back(partition.block_of[i]);
    share.contained.push_back(partition.contained[i]);
  }
  for (std::size_t b : share.blocks) {
    std::vector<std::uint32_t>& own = share.own.emplace_back();
    std::vector<std::uint32_t>& halo = share.halo.emplace_back();
    for (std::uint32_t i : partition.atoms[b]) own.push_back(position[i]);
    for (std::uint32_t i : partition.halo[b]) halo.push_back(position[i]);
  }
  return share;
}

std::string block_share_bytes(const BlockShare& share) {
  std::string out;
  put(out, static_cast<std::uint64_t>(share.block_count));
  put(out, static_cast<std::uint64_t>(share.total_atoms));
  put(out, share.origin);
  put(out, static_cast<std::uint64_t>(share.atoms.size()));
  for (const Atom& a : share.atoms) put_atom(out, a);
  put_array(out, share.global_index);
  put_array(out, share.block_of);
  put_array(out, share.contained);
  put(out, static_cast<std::uint64_t>(share.blocks.size()));
  for (std::size_t k = 0; k < share.blocks.size(); ++k) {
    put(out, static_cast<std::uint64_t>(share.blocks[k]));
    put_array(out, share.own[k]);
    put_array(out, share.halo[k]);
  }
  return out;
}

BlockShare read_block_share(std::string_view bytes) {
  ByteReader in(bytes);
  BlockShare share;
  share.block_count = static_cast<std::size_t>(in.get<std::uint64_t>());
  share.total_atoms = static_cast<std::size_t>(in.get<std::uint64_t>());
  share.origin = in.get<Vec3>();
  const auto atoms = in.get<std::uint64_t>();
  if (atoms > bytes.size()) throw std::invalid_argument("block share bytes: more atoms than bytes");
  share.atoms.reserve(static_cast<std::size_t>(atoms));
  for (std::uint64_t k = 0; k < atoms; ++k) share.atoms.push_back(get_atom(in));
  share.global_index = in.get_array<std::uint32_t>();
  share.block_of = in.get_array<std::uint32_t>();
  share.contained = in.get_array<std::uint8_t>();
  const auto blocks = in.get<std::uint64_t>();
  if (blocks > bytes.size()) throw std::invalid_argument("block share bytes: more blocks than bytes");
  for (std::uint64_t k = 0; k < blocks; ++k) {
    share.blocks.push_back(static_cast<std::size_t>(in.get<std::uint64_t>()));
    share.own.push_back(in.get_array<std::uint32_t>());
    share.halo.push_back(in.get_array<std::uint32_t>());
  }
  const std::size_t held = share.atoms.size();
  const auto within = [held](const std::vector<std::uint32_t>& list) {
    return std::all_of(list.begin(), list.end(), [held](std::uint32_t i) { return i < held; });
  };
  if (!in.done() || share.global_index.size() != held || share.block_of.size() != held ||
      share.contained.size() != held || !std::is_sorted(share.global_index.begin(), share.global_index.end()) ||
      !std::all_of(share.own.begin(), share.own.end(), within) ||
      !std::all_of(share.halo.begin(), share.halo.end(), within))
    throw std::invalid_argument("block share bytes: inconsistent");
  return share;
}

BlockShare share_blocks(std::span<const Atom> atoms, const ComputeSurfaceOptions& options,
                        const BlockedSurfaceOptions& blocked) {
  BlockExchange* exchange = blocked.exchange;
  BlockShare share;
  std::optional<BlockJob> job;
  on_first_process(exchange, [&] { job = plan_block_job(atoms, options, blocked.blocks, blocked.streamed); });
  if (exchange != nullptr && exchange->size() > 1 && exchange->rank() != 0)
    return read_block_share(exchange->receive());
  // One share built, sent and released at a time: the first process never holds them all.
  if (exchange != nullptr)
    for (int r = 1; r < exchange->size(); ++r)
      exchange->send(r, block_share_bytes(share_of_process(atoms, job->partition, job->options.spheres, r,
                                                           exchange->size())));
  share.partition = std::move(job->partition);
  return share;
}

}  // namespace molsurf::blocks
