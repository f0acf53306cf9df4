#pragma once
// A material is composed of an equation of state, an optional strength model
// and an optional damage model, chosen when the case is read (style.md #2).
// Every call works on a whole batch (all points of the material): one virtual
// call per batch, never per point. The same Material::update serves FEM
// integration points, SPH particles and the material-point driver.
#include <array>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "materials/material_points.hpp"

namespace camouflet {

// Where and when an explosive is lit (programmed burn).
struct DetonationPoint {
  std::array<double, 3> position{};  // m (2-D: third component 0)
  double time = 0.0;                 // s, lighting time of the point itself
};

struct MaterialContext {
  double dt = 0.0;    // s, this step
  double time = 0.0;  // s, at the end of this step
};

class EquationOfState {
 public:
  virtual ~EquationOfState() = default;
  virtual std::string type() const = 0;
  // Density at which the material is stress free (kg/m^3): initial density of parts.
  virtual double reference_density() const = 0;
  // Initial specific internal energy (J/kg) at the reference state.
  virtual double reference_specific_energy() const { return 0.0; }
  // Declare history columns (called once, before resize).
  virtual void register_state(MaterialPoints& /*pts*/) const {}
  // Pressure and bulk sound speed of every point from `density`,
  // `specific_energy` and its history. With commit == false (the predictor of
  // the energy equation) it must leave history untouched; with commit == true
  // it may advance history (compaction, burn ...). Called twice per step.
  virtual void evaluate(MaterialPoints& pts, const MaterialContext& ctx, bool commit) const = 0;
  // Called once after the points are placed, with each point's initial
  // position (m; 2-D padded with 0) and the model's detonation points:
  // explosives set their lighting times here. Default: nothing.
  virtual void place(MaterialPoints& /*pts*/, std::span<const std::array<double, 3>> /*positions*/,
                     const std::vector<DetonationPoint>& /*detonations*/) const {}
  // An explosive under programmed burn: no pressure until it is lit, and compression lights it.
  // A dynamic relaxation holds its points still (the unreacted charge is a solid the soil rests
  // on; squeezed pressureless by the overburden it would burn before t = 0).
  virtual bool programmed_burn() const { return false; }
};

class StrengthModel {
 public:
  virtual ~StrengthModel() = default;
  virtual std::string type() const = 0;
  virtual void register_state(MaterialPoints& /*pts*/) const {}
  // Set shear_modulus (and any strength state) at the initial state.
  virtual void initialise(MaterialPoints& pts) const = 0;
  // On entry `deviator` holds the old deviator already rotated by the Jaumann
  // rate and `pressure` the new pressure. On exit `deviator` is the new
  // deviator after the elastic trial and the return map; plastic_strain,
  // plastic_strain_rate, shear_modulus (and temperature, damage where the
  // model owns them) are updated.
  virtual void update(MaterialPoints& pts, const MaterialContext& ctx) const = 0;
  // Friction angle phi (rad) of a frictional strength, for Jaky's K0 = 1 - sin(phi) of a
  // geostatic initial state; none for a strength without friction.
  virtual std::optional<double> friction_angle() const { return std::nullopt; }
};

class DamageModel {
 public:
  virtual ~DamageModel() = default;
  virtual std::string type() const = 0;
  virtual void register_state(MaterialPoints& /*pts*/) const {}
  // Runs after the strength update: advances `damage` and may soften the
  // stress it acts on (pressure, deviator).
  virtual void update(MaterialPoints& pts, const MaterialContext& ctx) const = 0;
};

class Material {
 public:
  Material(std::string name, std::shared_ptr<const EquationOfState> eos,
           std::shared_ptr<const StrengthModel> strength = nullptr,
           std::shared_ptr<const DamageModel> damage = nullptr);

  const std::string& name() const { return name_; }
  const EquationOfState& eos() const { return *eos_; }
  const StrengthModel* strength() const { return strength_.get(); }
  const DamageModel* damage() const { return damage_.get(); }
  double reference_density() const { return eos_->reference_density(); }

  // Size the batch to n points at the reference state (density, energy,
  // pressure, sound speed, shear modulus) with every history column declared.
  // Room temperature is 300 K unless the strength model sets another.
  void setup(MaterialPoints& pts, std::size_t n) const;

  // The constitutive update of one step for every point of the batch:
  // Jaumann rotation of the deviator, EOS with the energy equation
  // (predictor-corrector on p dv, plus q dv and the deviatoric work), strength
  // with return map, damage. Inputs: density, density_previous, strain_rate,
  // spin, artificial_viscosity (set by the kinematics).
  void update(MaterialPoints& pts, const MaterialContext& ctx) const;

 private:
  std::string name_;
  std::shared_ptr<const EquationOfState> eos_;
  std::shared_ptr<const StrengthModel> strength_;
  std::shared_ptr<const DamageModel> damage_;
};

}  // namespace camouflet
