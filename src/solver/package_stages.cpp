// The registered packages' parts of the stages of step() (solver.cpp lists them all;
// core/package.hpp is the interface): each stage calls every package in the order of
// registration, after the FEM and SPH parts of the same stage.
#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "solver/solver.hpp"

namespace camouflet {

template <int D>
void Solver<D>::add_package(std::unique_ptr<Package<D>> package) {
  if (cycle_ != 0) throw std::logic_error("add_package: before the first step");
  if (!package) throw std::logic_error("add_package: no package");
  for (const auto& other : packages_)
    if (other->name() == package->name())
      throw std::logic_error("add_package: a package named '" + package->name() + "' is registered already");
  packages_.push_back(std::move(package));
  // The balance at t = 0 and the first step count the new package like every later one.
  gather_element_state();
  start_energy_and_step();
}

template <int D>
void Solver<D>::add_package_forces() {
  if (packages_.empty()) return;
  std::array<double, 3> g{};
  if (model_.run.has_gravity()) g = model_.run.gravity;
  double power = 0.0;
  for (const auto& package : packages_) power += package->add_forces(time_, g);
  // Over the step t_(n-1) -> t_n at v(n-1/2), as add_gravity books the nodes' and particles'.
  const double work = power * dt_;
  energy_.boundary_work += work;
  split_.gravity += work;
}

template <int D>
void Solver<D>::kick_packages() {
  for (const auto& package : packages_) package->kick(centred_step());
}

template <int D>
void Solver<D>::drift_packages() {
  package_kinetic_ = 0.0;
  for (const auto& package : packages_) package_kinetic_ += package->drift(dt_next_);
}

template <int D>
void Solver<D>::update_packages() {
  for (const auto& package : packages_) package->update_state(dt_, time_);
}

template <int D>
void Solver<D>::check_packages() const {
  for (const auto& package : packages_) {
    const std::string problem = package->check();
    if (!problem.empty())
      fail(NumericalError(EntityKind::model, 0, "package " + package->name(), problem));
  }
}

template <int D>
double Solver<D>::package_internal_energy() const {
  double internal = 0.0;
  for (const auto& package : packages_) internal += package->internal_energy();
  return internal;
}

template <int D>
void Solver<D>::vote_packages(double& dt, std::string& reason) const {
  const double cfl = model_.run.cfl;
  for (const auto& package : packages_) {
    const typename Package<D>::Vote vote = package->vote();
    if (cfl * vote.dt < dt || !(vote.dt >= 0.0)) {
      dt = cfl * vote.dt;
      reason = package->name() + ": " + vote.reason;
    }
  }
}

template void Solver<2>::add_package(std::unique_ptr<Package<2>>);
template void Solver<3>::add_package(std::unique_ptr<Package<3>>);
template void Solver<2>::add_package_forces();
template void Solver<3>::add_package_forces();
template void Solver<2>::kick_packages();
template void Solver<3>::kick_packages();
template void Solver<2>::drift_packages();
template void Solver<3>::drift_packages();
template void Solver<2>::update_packages();
template void Solver<3>::update_packages();
template void Solver<2>::check_packages() const;
template void Solver<3>::check_packages() const;
template double Solver<2>::package_internal_energy() const;
template double Solver<3>::package_internal_energy() const;
template void Solver<2>::vote_packages(double&, std::string&) const;
template void Solver<3>::vote_packages(double&, std::string&) const;

}  // namespace camouflet
