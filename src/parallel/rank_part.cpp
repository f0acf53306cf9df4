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
  if (!whole.bars.empty()) throw InputError(whole.bars.front().where, "embedded bars" + tail);
}

}  // namespace

RankPart::RankPart(const Communicator& comm, const Model& whole) : comm_(&comm) {
  refuse_what_does_not_cross_ranks(whole, comm.size());
  // Balanced by what the elements cost (a concrete element several elastic ones), not by count.
  const std::vector<int> part = partition_elements(whole.mesh, comm.size(), element_weights(whole));
  local_ = local_mesh(whole.mesh, part, comm.rank());
  // Everything but the mesh is the whole model's: materials, parts, boundaries by set name (the
  // sets cut to this rank, possibly empty), detonation points, erosion, the run's controls.
  // Every rank holds the whole model while it starts (each reads the case file): fine at the
  // sizes one node's memory takes, the limit docs/parallel.md gives for the partition too.
  model_ = whole;
  model_.mesh = std::move(local_.mesh);
}

}  // namespace camouflet
