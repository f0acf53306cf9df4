#pragma once
// The internal forces of FEM elements at t_n, pack by pack: stress divergence,
// hoop term and hourglass resistance of `width()` elements at once on SIMD
// lanes (element_pack.hpp). An index function: the forces of a pack depend on
// its elements alone, and go into the arrays the caller names; which packs run
// in which order, on which threads and into which arrays is the assembly's.
// The solver's assembly is the colour blocks of FemElements::add_internal_forces
// (fem_forces.cpp); bench/fem_assemblies.hpp keeps two others (per-thread
// buffers, single-element colours) for comparison (docs/performance.md,
// "Colouring against per-thread buffers").
//
// The interface speaks scalars and element numbers only, so that translation
// units built for another SIMD width than src/fem (bench/, tests/) can call it.
#include <cstddef>
#include <cstdint>

#include "fem/fem_elements.hpp"

namespace camouflet {

template <int D>
class ElementForceKernel {
 public:
  // One call's kernel: positions x (t_n), velocities v (t_(n-1/2)), the
  // run-wide hourglass control `hg` (elements with their own control use
  // theirs), dt_previous advancing the stiffness-form hourglass displacements.
  // r-z area-weighted momentum: the ring factors are refreshed here if stale.
  ElementForceKernel(FemElements<D>& elements, const double* x, const double* v, const HourglassControl& hg,
                     double dt_previous);

  static int width();  // elements per pack: the SIMD width src/fem is built for

  // f_out (n*D) += the forces of elements first .. first + count - 1 (count <= width()), and
  // fh_out (n*D, may be null) += their viscous-form hourglass part, lane by lane, node by node.
  // Advances the elements' stiffness-form hourglass displacements; returns the energy they hold (J).
  double consecutive(std::size_t first, int count, double* f_out, double* fh_out) const;
  // The same for the elements element[0 .. count - 1] (0-based numbers).
  double listed(const std::uint32_t* element, int count, double* f_out, double* fh_out) const;
  // As consecutive, each element's node forces unsummed: element e's node a (its a-th in the
  // connectivity) at slot e * nodes + a of f_slots (elements*nodes*D, values D per slot; fh_slots
  // alike, may be null), overwritten. For an assembly that adds them up node by node in an order
  // of its choosing (bench/fem_assemblies.hpp: in ascending element number, the same on any
  // number of threads or ranks).
  double consecutive_into_slots(std::size_t first, int count, double* f_slots, double* fh_slots) const;

  // Whether any element holds stiffness-form energy (an assembly then sums it pack by pack).
  bool holds_stiffness_energy() const { return any_stiff_hg_; }

 private:
  template <class Lanes, bool into_slots = false>
  double pack(const Lanes& lanes, double* f_out, double* fh_out) const;

  FemElements<D>& elements_;
  const double* x_;
  const double* v_;
  double dt_previous_;
  bool axi_, area_, own_hg_, hg_stiff_, any_stiff_hg_;
  double hg_kappa_;
};

}  // namespace camouflet
