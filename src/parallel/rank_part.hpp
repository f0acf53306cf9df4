#pragma once
// This rank's part of a run spread over several MPI ranks (docs/parallel.md): the whole model
// partitioned among the ranks (METIS, parallel/partition.hpp), cut to this rank's elements and
// the nodes they use (parallel/local_mesh.hpp), and the NodeSharing (model/node_sharing.hpp)
// through which the FEM package adds up the shares of the nodes it holds with other ranks. The
// solver steps the cut model (Solver(const RankPart&)) and takes its global decisions (the time
// step, the energy balance) through comm().
#include <cstdint>
#include <vector>

#include "model/model.hpp"
#include "model/node_sharing.hpp"
#include "parallel/communicator.hpp"
#include "parallel/local_mesh.hpp"

namespace camouflet {

class RankPart final : public NodeSharing {
 public:
  // Every rank calls it with the same whole model (each partitions it alike: METIS's seed is
  // fixed). What does not cross ranks yet is refused with an InputError at its case key: SPH
  // particles and what joins them to the mesh, and slide surfaces. `comm` must
  // outlive the part.
  RankPart(const Communicator& comm, const Model& whole);

  const Communicator& comm() const { return *comm_; }
  const Model& model() const { return model_; }  // the model cut to this rank
  // The cut's numbering and its neighbours; its mesh has moved into model().mesh.
  const LocalMesh& local() const { return local_; }

  void sum_shared(std::span<double> values, int components) const override {
    sum_shared_nodes(*comm_, local_, values, components);
  }
  const std::vector<char>& owned_nodes() const override { return local_.owned; }
  const std::vector<std::int64_t>& global_nodes() const override { return local_.global_node; }
  const std::vector<std::int64_t>& global_elements() const override { return local_.global_element; }
  const BarShare* bar_share() const override { return bars_.hosts.node_count() > 0 ? &bars_ : nullptr; }

 private:
  const Communicator* comm_;
  LocalMesh local_;
  BarShare bars_;
  Model model_;
};

}  // namespace camouflet
