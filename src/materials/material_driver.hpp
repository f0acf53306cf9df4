#pragma once
// The material-point driver: one point of a Material driven along a prescribed
// strain (or mixed strain/stress) path through Material::setup and
// Material::update, the exact code path of FEM integration points and SPH
// particles. This is how materials are calibrated and checked
// (`camouflet material-test`) and what the material tests build on.
//
// Conventions: x is the axial direction, y and z the lateral ones. Strain
// rates are logarithmic (true) rates, 1/s; a negative axial rate shortens the
// sample (compression). Density follows the volumetric strain exactly,
// rho_new = rho_old exp(-tr D dt). Stresses are tension positive, pressure
// compression positive.
#include <array>
#include <iosfwd>
#include <string>
#include <vector>

#include "materials/material.hpp"

namespace camouflet {

enum class LoadPath {
  uniaxial_strain,  // D = diag(rate, 0, 0)
  uniaxial_stress,  // D = diag(rate, d, d) with d iterated so that sigma_yy = sigma_zz = 0
  hydrostatic,      // D = diag(rate, rate, rate)
  triaxial,         // hydrostatic to the confining pressure, then axial at `strain_rate` with
                    // the lateral stress held at -confining_pressure
  simple_shear      // v_x = gamma_dot y: D_xy = W_xy = gamma_dot / 2; "axial strain" is gamma
};

// Parses "uniaxial_strain", "uniaxial-strain" ...; throws std::invalid_argument otherwise.
LoadPath parse_load_path(const std::string& name);
const char* to_string(LoadPath path);

struct DriverSpec {
  LoadPath path = LoadPath::uniaxial_strain;
  double strain_rate = -1.0;        // 1/s, axial (or shear) rate; negative = compression
  double final_strain = -0.01;      // axial true strain (shear strain gamma for simple_shear) reached at
                                    // the end; for triaxial: the axial strain of the compression phase
  double final_pressure = 0.0;      // Pa; hydrostatic only: when > 0 drive to this pressure instead
  double confining_pressure = 0.0;  // Pa, triaxial only
  int steps = 1000;                 // steps of the driven phase (triaxial: the same again to confine)
  double characteristic_length = 1.0e-3;  // m, given to the point (programmed burn ramps over it)
  // Explosives are lit at these points; by default the point itself at t = 0
  // (the point sits at the origin).
  std::vector<DetonationPoint> detonations{DetonationPoint{}};
  double stress_tolerance = 1.0e-9;  // relative tolerance on the held lateral stress
};

struct DriverRow {
  double time = 0.0;               // s
  double axial_strain = 0.0;       // true strain (gamma for simple shear)
  double volumetric_strain = 0.0;  // ln(V/V0) = -ln(rho/rho0), compression negative
  SymTensor stress;                // Pa, sigma = s - p I
  double pressure = 0.0;           // Pa
  double sqrt_j2 = 0.0;            // Pa
  double density = 0.0;            // kg/m^3
  double specific_energy = 0.0;    // J/kg
  double plastic_strain = 0.0;
  double damage = 0.0;
  double temperature = 0.0;  // K
};

// Drives the point; one row for the initial state and one per step. Throws
// std::invalid_argument for an impossible spec and NumericalError when the
// lateral stress cannot be held.
std::vector<DriverRow> drive_material(const Material& material, const DriverSpec& spec);

void write_driver_csv(std::ostream& out, const std::vector<DriverRow>& rows);

}  // namespace camouflet
