#pragma once
// The whole model's field snapshot assembled on rank 0 from every rank's part (docs/parallel.md),
// so that the output layer writes gauges and fields as in a serial run. Each node comes from the
// rank that owns it (every holder has the same bits), each element from the rank that steps it.
//
// The whole mesh passes through rank 0 once, for the output to locate its gauges; from then on
// (restrict_to) only the nodes and elements the gauges read do, whatever the mesh's size: field
// snapshots are each rank's own piece (.pvtu).
#include <cstdint>
#include <span>
#include <vector>

#include "core/sym_tensor.hpp"
#include "model/snapshot.hpp"
#include "parallel/rank_part.hpp"

namespace camouflet {

class WholeSnapshot {
 public:
  // `whole`: the model every rank started from (its mesh gives the counts and the connectivity).
  explicit WholeSnapshot(const Model& whole) : whole_(&whole) {}
  // Every rank calls it with its own snapshot; on rank 0 the returned view holds the whole
  // model's fields (valid until the next call), elsewhere an empty view.
  const FieldSnapshot& gather(const RankPart& part, const FieldSnapshot& mine);
  // From now on every gather carries only these nodes and elements (0-based in the whole mesh):
  // on rank 0 the view's other entries are NaN (material -1), so that a reader that strays
  // beyond them shows. Every rank calls it with the same lists.
  void restrict_to(const RankPart& part, std::span<const std::int64_t> nodes,
                   std::span<const std::int64_t> elements);

 private:
  const Model* whole_;
  bool restricted_ = false, blanked_ = false;
  std::vector<std::size_t> nodes_, elements_;  // local indices packed when restricted
  FieldSnapshot view_;
  std::vector<double> position_, displacement_, velocity_, acceleration_;
  std::vector<double> density_, pressure_, plastic_strain_, damage_, temperature_;
  std::vector<SymTensor> stress_;
  std::vector<int> material_;
};

}  // namespace camouflet
