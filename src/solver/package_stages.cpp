// The packages' parts of the stages of step() (solver.cpp lists them all; model/package.hpp
// is the interface): each stage calls every package in packages_' order, the SPH particles
// first, then those registered with add_package.
#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "solver/solver.hpp"

namespace camouflet {

template <int D>
void Solver<D>::add_package(std::unique_ptr<Package<D>> package) {
  if (cycle_ != 0) throw std::logic_error("add_package: before the first step");
  register_package(std::move(package));
  // The balance at t = 0 and the first step count the new package like every later one.
  gather_element_state();
  start_energy_and_step();
}

template <int D>
void Solver<D>::register_package(std::unique_ptr<Package<D>> package) {
  if (!package) throw std::logic_error("add_package: no package");
  for (const auto& other : packages_)
    if (other->name() == package->name())
      throw std::logic_error("add_package: a package named '" + package->name() + "' is registered already");
  split_.packages.push_back({package->name()});
  packages_.push_back(std::move(package));
}

template <int D>
void Solver<D>::add_package_forces() {
  for (const auto& package : packages_) package->add_forces(time_);
}

template <int D>
void Solver<D>::add_package_gravity(const std::array<double, 3>& g, double& power) {
  for (const auto& package : packages_) package->add_gravity(g, power);
}

template <int D>
void Solver<D>::kick_packages() {
  for (const auto& package : packages_) package->kick(centred_step());
}

template <int D>
void Solver<D>::drift_packages() {
  package_kinetic_ = 0.0;
  for (std::size_t k = 0; k < packages_.size(); ++k) {
    const double kinetic = packages_[k]->drift(dt_next_);
    split_.packages[k].kinetic = kinetic;
    package_kinetic_ += kinetic;
  }
}

template <int D>
void Solver<D>::update_packages() {
  for (const auto& package : packages_) package->update_state(dt_, time_);
}

template <int D>
void Solver<D>::check_packages() const {
  for (const auto& package : packages_) package->check();
}

template <int D>
double Solver<D>::package_internal_energy() {
  double internal = 0.0;
  for (std::size_t k = 0; k < packages_.size(); ++k) {
    split_.packages[k].internal = packages_[k]->internal_energy();
    internal += split_.packages[k].internal;
  }
  return internal;
}

template <int D>
double Solver<D>::package_kinetic_energy() const {
  double kinetic = 0.0;
  for (const auto& package : packages_) kinetic += package->kinetic_energy();
  return kinetic;
}

template <int D>
void Solver<D>::vote_packages(double& dt, std::string& reason) const {
  const double cfl = model_.run.cfl;
  for (const auto& package : packages_) {
    const typename Package<D>::Vote vote = package->vote();
    if (cfl * vote.dt < dt || !(vote.dt >= 0.0)) {
      dt = cfl * vote.dt;
      reason = vote.reason;
    }
  }
}

template <int D>
std::string Solver<D>::describe_package_point(EntityKind kind, std::int64_t id) const {
  for (const auto& package : packages_) {
    std::string text = package->describe(kind, id);
    if (!text.empty()) return text;
  }
  return {};
}

template <int D>
void Solver<D>::visit_package_state(StateVisitor& visitor) {
  for (const auto& package : packages_) package->visit_state(visitor);
}

template void Solver<2>::add_package(std::unique_ptr<Package<2>>);
template void Solver<3>::add_package(std::unique_ptr<Package<3>>);
template void Solver<2>::register_package(std::unique_ptr<Package<2>>);
template void Solver<3>::register_package(std::unique_ptr<Package<3>>);
template void Solver<2>::add_package_forces();
template void Solver<3>::add_package_forces();
template void Solver<2>::add_package_gravity(const std::array<double, 3>&, double&);
template void Solver<3>::add_package_gravity(const std::array<double, 3>&, double&);
template void Solver<2>::kick_packages();
template void Solver<3>::kick_packages();
template void Solver<2>::drift_packages();
template void Solver<3>::drift_packages();
template void Solver<2>::update_packages();
template void Solver<3>::update_packages();
template void Solver<2>::check_packages() const;
template void Solver<3>::check_packages() const;
template double Solver<2>::package_internal_energy();
template double Solver<3>::package_internal_energy();
template double Solver<2>::package_kinetic_energy() const;
template double Solver<3>::package_kinetic_energy() const;
template void Solver<2>::vote_packages(double&, std::string&) const;
template void Solver<3>::vote_packages(double&, std::string&) const;
template std::string Solver<2>::describe_package_point(EntityKind, std::int64_t) const;
template std::string Solver<3>::describe_package_point(EntityKind, std::int64_t) const;
template void Solver<2>::visit_package_state(StateVisitor&);
template void Solver<3>::visit_package_state(StateVisitor&);

}  // namespace camouflet
