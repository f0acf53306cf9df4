#include "parallel/communicator.hpp"

// MPI's C interface only: the C++ bindings are deprecated and need their own library.
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

namespace camouflet {

namespace {

// MPI's world, made by a ParallelSession after MPI_Init_thread.
class MpiCommunicator final : public Communicator {
 public:
  MpiCommunicator() {
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
  int rank() const override { return rank_; }
  int size() const override { return size_; }
  std::vector<double> all_gather(std::span<const double> values) const override {
    std::vector<double> all(values.size() * static_cast<std::size_t>(size_));
    MPI_Allgather(values.data(), static_cast<int>(values.size()), MPI_DOUBLE, all.data(),
                  static_cast<int>(values.size()), MPI_DOUBLE, MPI_COMM_WORLD);
    return all;
  }
  std::vector<std::int64_t> all_gather(std::span<const std::int64_t> values) const override {
    std::vector<std::int64_t> all(values.size() * static_cast<std::size_t>(size_));
    MPI_Allgather(values.data(), static_cast<int>(values.size()), MPI_INT64_T, all.data(),
                  static_cast<int>(values.size()), MPI_INT64_T, MPI_COMM_WORLD);
    return all;
  }
  void exchange(std::span<const int> ranks, const std::vector<std::vector<double>>& sends,
                std::vector<std::vector<double>>& receives) const override {
    constexpr int tag = 7;
    std::vector<MPI_Request> requests(2 * ranks.size());
    for (std::size_t i = 0; i < ranks.size(); ++i)
      MPI_Irecv(receives[i].data(), static_cast<int>(receives[i].size()), MPI_DOUBLE, ranks[i], tag,
                MPI_COMM_WORLD, &requests[i]);
    for (std::size_t i = 0; i < ranks.size(); ++i)
      MPI_Isend(sends[i].data(), static_cast<int>(sends[i].size()), MPI_DOUBLE, ranks[i], tag, MPI_COMM_WORLD,
                &requests[ranks.size() + i]);
    MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
  }
  void broadcast(std::vector<char>& bytes, int root) const override {
    std::uint64_t n = bytes.size();
    MPI_Bcast(&n, 1, MPI_UINT64_T, root, MPI_COMM_WORLD);
    bytes.resize(n);
    // In pieces below 2^31 bytes: MPI's counts are int.
    constexpr std::uint64_t piece = 1u << 30;
    for (std::uint64_t at = 0; at < n; at += piece)
      MPI_Bcast(bytes.data() + at, static_cast<int>(std::min(piece, n - at)), MPI_CHAR, root, MPI_COMM_WORLD);
  }
  void barrier() const override { MPI_Barrier(MPI_COMM_WORLD); }

 private:
  int rank_ = 0, size_ = 1;
};

const SerialCommunicator serial_world;
const Communicator* current_world = &serial_world;
bool mpi_initialised_here = false;

}  // namespace

double Communicator::sum(double value) const {
  sum(std::span<double>(&value, 1));
  return value;
}

std::int64_t Communicator::sum(std::int64_t value) const {
  if (size() == 1) return value;
  std::int64_t total = 0;
  for (std::int64_t v : all_gather(std::span<const std::int64_t>(&value, 1))) total += v;
  return total;
}

void Communicator::sum(std::span<double> values) const {
  if (size() == 1) return;
  const std::vector<double> all = all_gather(std::span<const double>(values.data(), values.size()));
  for (std::size_t i = 0; i < values.size(); ++i) {
    double total = 0.0;
    for (int r = 0; r < size(); ++r) total += all[static_cast<std::size_t>(r) * values.size() + i];
    values[i] = total;
  }
}

namespace {

// The value `better` picks over all ranks, and its rank: the lowest rank on a tie.
template <class Better>
Communicator::Located located(const Communicator& c, double value, Better better) {
  if (c.size() == 1) return {value, 0};
  const std::vector<double> all = c.all_gather(std::span<const double>(&value, 1));
  Communicator::Located best{all[0], 0};
  for (int r = 1; r < c.size(); ++r)
    if (better(all[static_cast<std::size_t>(r)], best.value)) best = {all[static_cast<std::size_t>(r)], r};
  return best;
}

}  // namespace

Communicator::Located Communicator::min(double value) const {
  return located(*this, value, [](double a, double b) { return a < b; });
}

Communicator::Located Communicator::max(double value) const {
  return located(*this, value, [](double a, double b) { return a > b; });
}

bool Communicator::any(bool flag) const {
  return sum(static_cast<std::int64_t>(flag ? 1 : 0)) > 0;
}

std::vector<double> SerialCommunicator::all_gather(std::span<const double> values) const {
  return {values.begin(), values.end()};
}

std::vector<std::int64_t> SerialCommunicator::all_gather(std::span<const std::int64_t> values) const {
  return {values.begin(), values.end()};
}

void SerialCommunicator::exchange(std::span<const int> ranks, const std::vector<std::vector<double>>&,
                                  std::vector<std::vector<double>>&) const {
  if (!ranks.empty()) throw std::logic_error("SerialCommunicator::exchange: a serial run has no other rank");
}

bool started_by_mpi_launcher() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
    if (std::getenv(name) != nullptr) return true;
  return false;
}

ParallelSession::ParallelSession(int& argc, char**& argv) {
  if (!started_by_mpi_launcher()) return;
  int initialised = 0;
  MPI_Initialized(&initialised);
  if (initialised)
    throw std::logic_error("ParallelSession: MPI is already initialised (one session per process)");
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  mpi_initialised_here = true;
  world_ = std::make_unique<MpiCommunicator>();
  current_world = world_.get();
}

ParallelSession::~ParallelSession() {
  if (!mpi_initialised_here) return;
  current_world = &serial_world;
  world_.reset();
  MPI_Finalize();
  mpi_initialised_here = false;
}

const Communicator& world() {
  return *current_world;
}

void abort_world(int code) {
  if (mpi_initialised_here) MPI_Abort(MPI_COMM_WORLD, code);
  std::exit(code);
}

}  // namespace camouflet
