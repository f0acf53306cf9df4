#pragma once
// The ranks a run is spread over and the decisions they take together (docs/parallel.md).
//
// A process started by mpirun works in MPI's world; any other in a serial communicator of one
// rank that never touches MPI and costs nothing, so `camouflet run CASE` stays what it was.
// Every reduction is deterministic and gives the same bits on every rank: the ranks' values are
// gathered to all of them in rank order and combined in that order, whatever tree MPI's own
// reductions would take. That costs a gather where a reduction would do, which at one value (or a
// few dozen: the energy terms) per step is nothing beside the step.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace camouflet {

class Communicator {
 public:
  virtual ~Communicator() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;

  // Every rank's values, rank after rank (each rank gives the same count).
  virtual std::vector<double> all_gather(std::span<const double> values) const = 0;
  virtual std::vector<std::int64_t> all_gather(std::span<const std::int64_t> values) const = 0;
  // Point to point with neighbours: sends[i] to ranks[i] and receives[i] (sized by the caller to
  // what ranks[i] sends) from it, all at once (non-blocking, then waited for).
  virtual void exchange(std::span<const int> ranks, const std::vector<std::vector<double>>& sends,
                        std::vector<std::vector<double>>& receives) const = 0;
  // root's bytes onto every rank (resized to root's size).
  virtual void broadcast(std::vector<char>& bytes, int root) const = 0;
  virtual void barrier() const = 0;

  // Sums over the ranks, added in rank order.
  double sum(double value) const;
  std::int64_t sum(std::int64_t value) const;
  void sum(std::span<double> values) const;  // element by element, in place
  // The smallest (largest) value and the rank that holds it, the lowest rank on a tie.
  struct Located {
    double value = 0.0;
    int rank = 0;
  };
  Located min(double value) const;
  Located max(double value) const;
  // True on every rank when it is on any.
  bool any(bool flag) const;
};

// One rank, no MPI.
class SerialCommunicator final : public Communicator {
 public:
  int rank() const override { return 0; }
  int size() const override { return 1; }
  std::vector<double> all_gather(std::span<const double> values) const override;
  std::vector<std::int64_t> all_gather(std::span<const std::int64_t> values) const override;
  void exchange(std::span<const int> ranks, const std::vector<std::vector<double>>&,
                std::vector<std::vector<double>>&) const override;
  void broadcast(std::vector<char>&, int) const override {}
  void barrier() const override {}
};

// True when this process was started by an MPI launcher (Open MPI's mpirun, or any PMI/PMIx one).
bool started_by_mpi_launcher();

// Made first thing in main(): initialises MPI when the process was started by an MPI launcher
// (funneled threads: only the thread that steps the model talks to other ranks) and finalises it
// when destroyed. Without one, or started without a launcher, world() is serial.
class ParallelSession {
 public:
  ParallelSession(int& argc, char**& argv);
  ~ParallelSession();
  ParallelSession(const ParallelSession&) = delete;
  ParallelSession& operator=(const ParallelSession&) = delete;

 private:
  std::unique_ptr<Communicator> world_;
};

// The world of this process: MPI's when a ParallelSession initialised it, else serial.
const Communicator& world();

// Stops every rank of the world with the exit code (MPI_Abort); a serial world just exits.
[[noreturn]] void abort_world(int code);

}  // namespace camouflet
