// The packages' stages of step() (solver.cpp lists them all; model/package.hpp is the
// interface): each calls every package in packages_' order (FEM, the SPH particles, then those
// registered with add_package), drift and update in the reverse order (package.hpp says why).
#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "solver/solver.hpp"

namespace camouflet {

template <int D>
void Solver<D>::add_package(std::unique_ptr<Package<D>> package) {
  if (cycle_ != 0) throw std::logic_error("add_package: before the first step");
  if (!package) throw std::logic_error("add_package: no package");
  register_package(std::move(package));
  // The balance at t = 0 and the first step count the new package like every later one.
  gather_energies();
  start_energy_and_step();
}

template <int D>
void Solver<D>::register_package(Package<D>& package) {
  for (const Package<D>* other : packages_)
    if (other->name() == package.name())
      throw std::logic_error("add_package: a package named '" + package.name() + "' is registered already");
  split_.packages.push_back({package.name()});
  packages_.push_back(&package);
}

template <int D>
void Solver<D>::register_package(std::unique_ptr<Package<D>> package) {
  register_package(*package);
  owned_packages_.push_back(std::move(package));
}

template <int D>
void Solver<D>::begin_packages() {
  for (Package<D>* package : packages_) package->begin_step(clock());
}

template <int D>
void Solver<D>::add_package_forces() {
  for (Package<D>* package : packages_) package->add_forces(clock());
}

template <int D>
void Solver<D>::kick_packages() {
  for (Package<D>* package : packages_) package->kick(clock());
}

template <int D>
void Solver<D>::drift_packages() {
  for (std::size_t k = packages_.size(); k-- > 0;) split_.packages[k].kinetic = packages_[k]->drift(clock());
}

template <int D>
void Solver<D>::check_packages() const {
  for (const Package<D>* package : packages_) package->check();
}

template <int D>
void Solver<D>::update_packages() {
  for (std::size_t k = packages_.size(); k-- > 0;) packages_[k]->update_state(clock(), energy_);
}

template <int D>
void Solver<D>::gather_energies() {
  double internal = 0.0;
  for (std::size_t k = 0; k < packages_.size(); ++k) {
    split_.packages[k].internal = packages_[k]->internal_energy();
    internal += split_.packages[k].internal;
  }
  split_.bar_internal = fem_.bars.internal_energy();  // energy.csv's bar column, part of FEM's share
  internal_energy_ = internal;
}

template <int D>
double Solver<D>::package_kinetic_energy() const {
  double kinetic = 0.0;
  for (const Package<D>* package : packages_) kinetic += package->kinetic_energy();
  return kinetic;
}

template <int D>
double Solver<D>::package_hourglass_energy() const {
  double hourglass = 0.0;
  for (const Package<D>* package : packages_) hourglass += package->hourglass_energy();
  return hourglass;
}

template <int D>
std::string Solver<D>::describe(EntityKind kind, std::int64_t id) const {
  for (const Package<D>* package : packages_) {
    std::string text = package->describe(kind, id);
    if (!text.empty()) return text;
  }
  return {};
}

template <int D>
void Solver<D>::visit_package_state(StateVisitor& visitor) {
  for (Package<D>* package : packages_) package->visit_state(visitor);
}

template void Solver<2>::add_package(std::unique_ptr<Package<2>>);
template void Solver<3>::add_package(std::unique_ptr<Package<3>>);
template void Solver<2>::register_package(Package<2>&);
template void Solver<3>::register_package(Package<3>&);
template void Solver<2>::register_package(std::unique_ptr<Package<2>>);
template void Solver<3>::register_package(std::unique_ptr<Package<3>>);
template void Solver<2>::begin_packages();
template void Solver<3>::begin_packages();
template void Solver<2>::add_package_forces();
template void Solver<3>::add_package_forces();
template void Solver<2>::kick_packages();
template void Solver<3>::kick_packages();
template void Solver<2>::drift_packages();
template void Solver<3>::drift_packages();
template void Solver<2>::check_packages() const;
template void Solver<3>::check_packages() const;
template void Solver<2>::update_packages();
template void Solver<3>::update_packages();
template void Solver<2>::gather_energies();
template void Solver<3>::gather_energies();
template double Solver<2>::package_kinetic_energy() const;
template double Solver<3>::package_kinetic_energy() const;
template double Solver<2>::package_hourglass_energy() const;
template double Solver<3>::package_hourglass_energy() const;
template std::string Solver<2>::describe(EntityKind, std::int64_t) const;
template std::string Solver<3>::describe(EntityKind, std::int64_t) const;
template void Solver<2>::visit_package_state(StateVisitor&);
template void Solver<3>::visit_package_state(StateVisitor&);

}  // namespace camouflet
