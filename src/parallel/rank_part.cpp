#include "parallel/rank_part.hpp"

#include <fmt/format.h>

#include "core/error.hpp"
#include "parallel/element_weights.hpp"
#include "parallel/partition.hpp"

namespace camouflet {

namespace {

// The first thing of `whole` that a run across ranks cannot step yet, refused at its key.
void refuse_what_does_not_cross_ranks(const Model& whole, int ranks) {
  const std::string tail = fmt::format(" in a run across MPI ranks ({}) is not there yet: run this case on one rank", ranks);
  if (whole.particles.count() > 0) {
    for (const Part& part : whole.parts)
      if (part.kind == PartKind::sph) throw InputError(part.where, "SPH part '" + part.name + "'" + tail);
    throw InputError(whole.run.where, "SPH particles" + tail);
  }
  if (!whole.joins.empty()) throw InputError(whole.joins.front().where, "an SPH-FEM join" + tail);
  if (!whole.contacts.empty()) throw InputError(whole.contacts.front().where, "an SPH-FEM contact" + tail);
  if (!whole.slide_surfaces.empty()) throw InputError(whole.slide_surfaces.front().where, "a slide surface" + tail);
}

// The bar nodes' hosts in the whole mesh, which of them this rank's elements host, and for every
// rank the nodes its segments reach beyond its elements: a segment is stepped by the rank hosting
// its first node, which then holds the host element of its second node too.
std::vector<std::vector<std::int64_t>> share_bars(const Model& whole, std::span<const int> part, int rank,
                                                  BarShare& share) {
  std::vector<std::vector<std::int64_t>> extra;
  if (whole.bars.empty()) return {};
  share.hosts = locate_bar_nodes(whole, whole.mesh.coordinates);
  const BarHosts& hosts = share.hosts;
  const auto rank_of = [&](std::size_t b) { return part[static_cast<std::size_t>(hosts.element[b])]; };
  share.hosted_here.resize(hosts.node_count());
  for (std::size_t b = 0; b < hosts.node_count(); ++b) share.hosted_here[b] = rank_of(b) == rank ? 1 : 0;
  std::size_t first = 0;
  for (const BarSet& set : whole.bars) {
    for (std::size_t s = 0; s < static_cast<std::size_t>(set.segments); ++s) {
      const std::size_t i = first + s, j = i + 1;
      const auto r = static_cast<std::size_t>(rank_of(i));
      if (rank_of(j) == rank_of(i)) continue;
      if (extra.size() <= r) extra.resize(r + 1);
      for (int a = 0; a < hosts.host_nodes; ++a)
        extra[r].push_back(hosts.node[j * static_cast<std::size_t>(hosts.host_nodes) + static_cast<std::size_t>(a)]);
    }
    first += static_cast<std::size_t>(set.segments) + 1;
  }
  return extra;
}

}  // namespace

RankPart::RankPart(const Communicator& comm, const Model& whole) : comm_(&comm) {
  refuse_what_does_not_cross_ranks(whole, comm.size());
  // Balanced by what the elements cost (a concrete element several elastic ones), not by count.
  const std::vector<int> part = partition_elements(whole.mesh, comm.size(), element_weights(whole));
  const std::vector<std::vector<std::int64_t>> bar_nodes = share_bars(whole, part, comm.rank(), bars_);
  local_ = local_mesh(whole.mesh, part, comm.rank(), bar_nodes);
  // Everything but the mesh is the whole model's: materials, parts, boundaries by set name (the
  // sets cut to this rank, possibly empty), detonation points, erosion, the run's controls.
  // Every rank holds the whole model while it starts (each reads the case file): fine at the
  // sizes one node's memory takes, the limit docs/parallel.md gives for the partition too.
  model_ = whole;
  model_.mesh = std::move(local_.mesh);
}

}  // namespace camouflet
