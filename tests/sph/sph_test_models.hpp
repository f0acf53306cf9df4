#pragma once
// Small builders for the SPH tests: materials from the registry (the same
// factories a case file uses), particle parts, and a fixed-CFL driver loop.
#include <omp.h>

#include <cmath>
#include <functional>
#include <memory>
#include <string>

#include "materials/registry.hpp"
#include "mesh/particle_fill.hpp"
#include "model/model.hpp"
#include "sph/sph_system.hpp"

namespace camouflet::test {

inline std::shared_ptr<const Material> ideal_gas(const std::string& name, double density, double gamma,
                                                 double specific_energy) {
  Parameters eos;
  eos.set_string("type", "ideal_gas");
  eos.set_number("density", density);
  eos.set_number("gamma", gamma);
  eos.set_number("specific_energy", specific_energy);
  return make_material(name, "", {}, eos, Parameters{}, Parameters{});
}

// Linear elastic solid: polynomial EOS p = K mu and Johnson-Cook with a yield
// stress far above anything the tests reach (so it stays elastic).
inline std::shared_ptr<const Material> elastic_solid(const std::string& name, double density, double bulk,
                                                     double shear) {
  Parameters eos, strength;
  eos.set_string("type", "polynomial");
  eos.set_number("density", density);
  eos.set_number("a1", bulk);
  strength.set_string("type", "johnson_cook");
  strength.set_number("shear_modulus", shear);
  strength.set_number("yield_stress", 1e6 * shear);
  strength.set_number("hardening_modulus", 0.0);
  strength.set_number("hardening_exponent", 1.0);
  strength.set_number("melt_temperature", 1e9);
  strength.set_number("specific_heat", 1e9);
  strength.set_bool("isothermal", true);
  return make_material(name, "", {}, eos, strength, Parameters{});
}

// Adds a material, an SPH part using it and its particles.
inline int add_sph_part(Model& model, const std::string& name, std::shared_ptr<const Material> material,
                        ParticleFillSpec spec, std::array<double, 3> velocity = {}) {
  model.materials.push_back({name, std::move(material), {}});
  Part part;
  part.name = name;
  part.kind = PartKind::sph;
  part.material = static_cast<int>(model.materials.size()) - 1;
  part.initial_velocity = velocity;
  model.parts.push_back(part);
  spec.part = static_cast<int>(model.parts.size()) - 1;
  fill_particles(model.particles, spec, model.run.mode);
  return spec.part;
}

// The 100 kg TNT sphere of the seed paper (tnt_wang2005, R = 0.2447 m at
// 1630 kg/m^3) as r-z particles of spacing R / n, lit at its centre on the axis.
inline Model tnt_sphere_rz(int n) {
  const double radius = 0.2447;  // m
  Model model;
  model.run.mode = GeometryMode::axisymmetric;
  ParticleFillSpec fill;
  fill.region.shape = ParticleRegion::Shape::sphere;
  fill.region.centre = {0, 0, 0};
  fill.region.radius = radius;
  fill.spacing = radius / n;
  add_sph_part(model, "tnt", make_material("tnt", "tnt_wang2005", {}, Parameters{}, Parameters{}, Parameters{}),
               fill);
  model.detonations.push_back(DetonationPoint{{0.0, 0.0, 0.0}, 0.0});
  return model;
}

inline ParticleFillSpec box_fill(std::array<double, 3> lo, std::array<double, 3> hi, double spacing) {
  ParticleFillSpec s;
  s.region.shape = ParticleRegion::Shape::box;
  s.region.min = lo;
  s.region.max = hi;
  s.spacing = spacing;
  return s;
}

// Steps to t_end with dt = cfl x the SPH stable step; returns the number of cycles.
// One thread: the test machine's cores are shared, and thousands of short
// parallel regions per second then wait on descheduled threads.
template <int D>
long run_until(sph::SphSystem<D>& system, double t_end, double cfl, long max_cycles = 1000000) {
  omp_set_num_threads(1);
  double t = 0.0;
  long cycles = 0;
  system.compute_accelerations();
  while (t < t_end * (1.0 - 1e-12) && cycles < max_cycles) {
    double dt = cfl * system.stable_time_step().dt;
    if (t + dt > t_end) dt = t_end - t;
    t += dt;
    system.step(dt, t);
    ++cycles;
  }
  return cycles;
}

// Where a variable-step leapfrog stands: its time, its last step and cycles so far.
struct LeapfrogClock {
  double t = 0.0, dt_previous = 0.0;
  long cycles = 0;
};

// Steps on from `clock` to t_end with the variable-step leapfrog of the solver (solver.cpp,
// FemPackage::kick): the kick at t_n spans the mean of the two half steps (the first one dt/2),
// so the scheme stays second order while the step changes from cycle to cycle; run_until() kicks
// with the new step and loses energy to first order when the step grows fast (a point blast's
// first cycles). The last step lands on t_end; the accelerations are computed on the first call.
template <int D>
void advance_leapfrog(sph::SphSystem<D>& system, LeapfrogClock& clock, double t_end, double cfl,
                      const std::function<void()>& after_each_cycle = {}) {
  if (clock.cycles == 0) system.compute_accelerations();
  while (clock.t < t_end * (1.0 - 1e-12)) {
    double dt = cfl * system.stable_time_step().dt;
    if (clock.t + dt > t_end) dt = t_end - clock.t;
    clock.t += dt;
    system.kick(0.5 * (clock.dt_previous + dt));
    system.drift(dt);
    system.update_state(dt, clock.t);
    system.compute_accelerations();
    clock.dt_previous = dt;
    ++clock.cycles;
    if (after_each_cycle) after_each_cycle();
  }
}

// From t = 0 to t_end on one thread (advance_leapfrog). Returns the number of cycles; the last
// step goes to *dt_last.
template <int D>
long run_leapfrog_until(sph::SphSystem<D>& system, double t_end, double cfl, double* dt_last = nullptr,
                        const std::function<void()>& after_each_cycle = {}) {
  omp_set_num_threads(1);
  LeapfrogClock clock;
  advance_leapfrog(system, clock, t_end, cfl, after_each_cycle);
  if (dt_last) *dt_last = clock.dt_previous;
  return clock.cycles;
}

// Kinetic energy at the time of the positions after run_leapfrog_until(),
// with v(n) = v(n-1/2) + a(n) dt/2 (J; axisymmetric: full revolution).
template <int D>
double synchronised_kinetic_energy(const sph::SphSystem<D>& system, double dt_last) {
  const auto& p = system.particles();
  double e = 0.0;
  for (std::size_t i = 0; i < system.size(); ++i) {
    const Vec<D> v = p.velocity[i] + p.acceleration[i] * (0.5 * dt_last);
    e += 0.5 * p.mass[i] * dot(v, v);
  }
  return e;
}

}  // namespace camouflet::test
