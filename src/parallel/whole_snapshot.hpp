#pragma once
// The whole model's field snapshot assembled on rank 0 from every rank's part (docs/parallel.md),
// so that the output layer writes gauges and fields as in a serial run. Each node comes from the
// rank that owns it (every holder has the same bits), each element from the rank that steps it.
//
// The whole mesh passes through rank 0 at every output: right for the sizes one node holds, not
// for 10^7 elements, where each rank will write its own piece (.pvtu) and its own gauges.
#include <cstdint>
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

 private:
  const Model* whole_;
  FieldSnapshot view_;
  std::vector<double> position_, displacement_, velocity_, acceleration_;
  std::vector<double> density_, pressure_, plastic_strain_, damage_, temperature_;
  std::vector<SymTensor> stress_;
  std::vector<int> material_;
};

}  // namespace camouflet
