// The solver's global decisions on ranks (solver.hpp; docs/parallel.md): the energy balance, the
// time step and a failure over every rank of a run spread over several, each taken from every
// rank's share in rank order, so that every rank holds the same bits.
#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "solver/solver.hpp"

namespace camouflet {

namespace {

// Every summed term of the balance and of its split, in one fixed order: the addresses of one
// balance's terms, so that a rank's shares and the whole run's pair up term by term.
template <class Split>
void terms(EnergyBalance& e, Split& s, std::vector<double*>& out) {
  out = {&e.kinetic, &e.internal, &e.hourglass, &e.viscous, &e.boundary_work, &e.eroded, &e.initial_total,
         &s.transmitting, &s.constraints, &s.join, &s.join_face, &s.contact, &s.bar_internal, &s.gravity};
  for (auto& share : s.packages) {
    out.push_back(&share.kinetic);
    out.push_back(&share.internal);
  }
}

}  // namespace

template <int D>
bool Solver<D>::reduce_energy(bool failed) {
  global_energy_ = energy_;
  global_split_ = split_;
  std::vector<double*> mine, whole;
  terms(energy_, split_, mine);
  terms(global_energy_, global_split_, whole);
  std::vector<double> values(mine.size() + 1);
  for (std::size_t k = 0; k < mine.size(); ++k) values[k] = *mine[k];
  values.back() = failed ? 1.0 : 0.0;
  ranks_->comm().sum(values);  // element by element, in rank order
  for (std::size_t k = 0; k < whole.size(); ++k) *whole[k] = values[k];
  set_relative_error(global_energy_);
  return values.back() > 0.0;
}

template <int D>
bool Solver<D>::reduce_time_step(double& dt, std::string& reason) const {
  const Communicator& comm = ranks_->comm();
  // A NaN vote (a broken element) must win everywhere: it stops every rank at once.
  const Communicator::Located smallest = comm.min(std::isnan(dt) ? -std::numeric_limits<double>::infinity() : dt);
  dt = smallest.value;
  std::vector<char> bytes(reason.begin(), reason.end());
  comm.broadcast(bytes, smallest.rank);
  reason.assign(bytes.begin(), bytes.end());
  return smallest.rank == comm.rank();
}

template <int D>
void Solver<D>::agree_on_failure(std::optional<NumericalError>& failure, int stage) const {
  const Communicator& comm = ranks_->comm();
  // The serial run stops at the first stage that fails, naming the first point of its loop: the
  // lowest id, as the ranks number their points in the order of the whole mesh.
  const double key = failure ? stage * 1e15 + static_cast<double>(failure->id())
                             : std::numeric_limits<double>::infinity();
  const int first = comm.min(key).rank;
  // The error travels as its fields, each ended by a nought: kind, id, quantity, detail and the
  // point as the failing rank describes it (it alone holds the element or node).
  std::vector<char> bytes;
  if (comm.rank() == first) {
    const auto put = [&bytes](const std::string& text) {
      bytes.insert(bytes.end(), text.begin(), text.end());
      bytes.push_back('\0');
    };
    put(std::to_string(static_cast<int>(failure->kind())));
    put(std::to_string(failure->id()));
    put(failure->quantity());
    put(failure->detail());
    put(describe(failure->kind(), failure->id()));
  }
  comm.broadcast(bytes, first);
  std::vector<std::string> fields;
  std::string field;
  for (char c : bytes) {
    if (c) {
      field.push_back(c);
    } else {
      fields.push_back(std::move(field));
      field.clear();
    }
  }
  if (fields.size() != 5) throw std::logic_error("agree_on_failure: a garbled error from rank " + std::to_string(first));
  NumericalError error(static_cast<EntityKind>(std::stoi(fields[0])), std::stoll(fields[1]), fields[2],
                       fields.size() > 3 ? fields[3] : std::string());
  error.set_context(cycle_, time_,
                    fields[4] + (comm.size() > 1 ? fmt::format(", on rank {} of {}", first, comm.size()) : ""));
  throw error;
}

template bool Solver<2>::reduce_energy(bool);
template bool Solver<3>::reduce_energy(bool);
template bool Solver<2>::reduce_time_step(double&, std::string&) const;
template bool Solver<3>::reduce_time_step(double&, std::string&) const;
template void Solver<2>::agree_on_failure(std::optional<NumericalError>&, int) const;
template void Solver<3>::agree_on_failure(std::optional<NumericalError>&, int) const;

}  // namespace camouflet
