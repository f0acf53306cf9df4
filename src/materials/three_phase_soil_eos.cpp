#include "materials/three_phase_soil_eos.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include "core/error.hpp"
#include "materials/registry.hpp"

namespace camouflet {

namespace {

constexpr double fraction_tolerance = 1e-6;

// History columns of the predictor's solution (see register_state); the
// pressures are absolute, as the law returns them.
constexpr const char* trial_columns[] = {
    "soil_trial_density",       "soil_trial_damage",       "soil_trial_pressure",
    "soil_trial_pore_pressure", "soil_trial_pore_volume",  "soil_trial_bulk_modulus",
    "soil_trial_branch",        "soil_trial_water_volume", "soil_trial_solid_volume",
    "soil_trial_release_modulus"};
constexpr int trial_count = sizeof trial_columns / sizeof trial_columns[0];

struct PhaseKeys {
  const char* density;
  const char* sound_speed;
  const char* exponent;
  double density_default, sound_speed_default, exponent_default;  // Wang et al. 2005, Table 2
};

TaitPhase read_tait(Parameters& p, const PhaseKeys& k, double fraction, double& density) {
  density = p.positive(k.density, k.density_default);
  const double c0 = p.positive(k.sound_speed, k.sound_speed_default);
  TaitPhase phase;
  phase.fraction = fraction;
  phase.bulk_modulus = density * c0 * c0;
  phase.exponent = p.positive(k.exponent, k.exponent_default);
  phase.inverse_exponent = 1.0 / phase.exponent;
  return phase;
}

// Volume fractions: given directly, or from porosity (or dry density) and
// saturation, which is how soils are usually described.
void read_fractions(Parameters& p, double grain_density, double& solid, double& water, double& air) {
  const bool direct = p.has("solid_fraction") || p.has("water_fraction") || p.has("air_fraction");
  if (direct) {
    for (const char* key : {"porosity", "dry_density", "saturation"})
      if (p.has(key)) p.fail(key, "give either the volume fractions or porosity/dry_density with saturation");
    solid = p.in_range("solid_fraction", 0.0, 1.0, 0.0);
    water = p.in_range("water_fraction", 0.0, 1.0, 0.0);
    air = p.in_range("air_fraction", 0.0, 1.0, 0.0);
    const double sum = solid + water + air;
    if (std::abs(sum - 1.0) > fraction_tolerance)
      p.fail("air_fraction",
             fmt::format("solid_fraction + water_fraction + air_fraction must be 1 (within {}), "
                         "got {} + {} + {} = {}",
                         fraction_tolerance, solid, water, air, sum));
    return;
  }
  double porosity = 0.0;
  if (p.has("dry_density")) {
    if (p.has("porosity")) p.fail("porosity", "give porosity or dry_density, not both");
    const double dry = p.positive("dry_density");
    if (!(dry < grain_density))
      p.fail("dry_density",
             fmt::format("must be below the grain density {} kg/m^3, got {}", grain_density, dry));
    porosity = 1.0 - dry / grain_density;
  } else {
    if (!p.has("porosity"))
      p.fail("solid_fraction", "give solid/water/air_fraction, or porosity with saturation");
    porosity = p.in_range("porosity", 0.0, 1.0, 0.0);
    if (!(porosity > 0.0)) p.fail("porosity", "must be positive: the model needs pore space");
  }
  if (!p.has("saturation")) p.fail("saturation", "required with porosity or dry_density");
  const double saturation = p.in_range("saturation", 0.0, 1.0, 0.0);
  solid = 1.0 - porosity;
  water = porosity * saturation;
  air = porosity * (1.0 - saturation);
}

}  // namespace

ThreePhaseSoilEos::ThreePhaseSoilEos(const ThreePhaseSoilConstants& constants, double reference_density)
    : constants_(constants), reference_density_(reference_density) {}

void ThreePhaseSoilEos::register_state(MaterialPoints& pts) const {
  pts.history.add("soil_min_volume", 1.0);
  pts.history.add("soil_max_pressure", 0.0);
  pts.history.add("soil_max_pore_pressure", 0.0);
  pts.history.add("soil_pore_pressure", 0.0);
  pts.history.add("soil_pore_volume", constants_.pore_fraction());
  pts.history.add("soil_eos_branch", 0.0);
  // Cache of v_w(p_b,max) and v_s(p_max), the unloading branch's fixed end
  // (exactly alpha_w and alpha_s at the reference state).
  pts.history.add("soil_max_water_volume", constants_.water.fraction);
  pts.history.add("soil_max_solid_volume", constants_.solid.fraction);
  // The predictor's solution and the inputs it was solved for. The law is
  // barotropic, so the corrector call at the same density, damage and
  // compaction has the same root: it takes this one instead of solving again.
  // NaN density = no trial pending.
  for (const char* name : trial_columns) pts.history.add(name, std::nan(""));
}

void ThreePhaseSoilEos::evaluate(MaterialPoints& pts, const MaterialContext& /*ctx*/, bool commit) const {
  const std::size_t n = pts.size();
  const double p0 = constants_.ambient_pressure;
  const double rho0 = reference_density_;
  double* min_volume = pts.history.column(pts.history.slot("soil_min_volume"));
  double* max_pressure = pts.history.column(pts.history.slot("soil_max_pressure"));
  double* max_pore_pressure = pts.history.column(pts.history.slot("soil_max_pore_pressure"));
  double* pore_pressure = pts.history.column(pts.history.slot("soil_pore_pressure"));
  double* pore_volume = pts.history.column(pts.history.slot("soil_pore_volume"));
  double* branch = pts.history.column(pts.history.slot("soil_eos_branch"));
  double* max_water_volume = pts.history.column(pts.history.slot("soil_max_water_volume"));
  double* max_solid_volume = pts.history.column(pts.history.slot("soil_max_solid_volume"));
  double* trial[trial_count];
  for (int k = 0; k < trial_count; ++k) trial[k] = pts.history.column(pts.history.slot(trial_columns[k]));
  double* const trial_density = trial[0];
  double* const trial_damage = trial[1];
  double* const trial_pressure = trial[2];
  double* const trial_pore_pressure = trial[3];
  double* const trial_pore_volume = trial[4];
  double* const trial_bulk_modulus = trial[5];
  double* const trial_branch = trial[6];
  double* const trial_water_volume = trial[7];
  double* const trial_solid_volume = trial[8];
  double* const trial_release_modulus = trial[9];

  // Exceptions may not leave an OpenMP region: the first failure is kept and
  // thrown after the loop.
  std::int64_t failed = -1;
  std::string failed_quantity, failed_detail;

// Small batches (a material-point driver, a few particles) run serially: a
// thread team costs more than the points.
#pragma omp parallel for schedule(static) if (n >= 256)
  for (std::size_t i = 0; i < n; ++i) {
    const double rho = pts.density[i];
    const double damage = pts.damage[i];
    SoilCompaction from{min_volume[i], max_pressure[i] + p0, max_pore_pressure[i] + p0};
    from.water_volume = max_water_volume[i];
    from.solid_volume = max_solid_volume[i];
    SoilState s;
    const bool density_ok = std::isfinite(rho) && rho > 0.0;
    // Warm starts: the pressure column holds the last solution (the previous
    // step in the predictor, the predictor's in the corrector); the skeleton
    // stress changes little over a step, so p - p_e,max guesses p_b.
    const double pressure_guess = pts.pressure[i] + p0;
    const double pore_guess = pressure_guess - (max_pressure[i] - max_pore_pressure[i]);
    // The corrector after a predictor at the same density and damage (the
    // compaction changes only here, and the pressure column still holds the
    // trial's): the same root, already converged.
    const bool reuse = commit && density_ok && trial_density[i] == rho && trial_damage[i] == damage &&
                       pts.pressure[i] == trial_pressure[i] - p0;
    if (reuse) {
      s.pressure = trial_pressure[i];
      s.pore_pressure = trial_pore_pressure[i];
      s.pore_volume = trial_pore_volume[i];
      s.bulk_modulus = trial_bulk_modulus[i];
      s.branch = static_cast<SoilBranch>(static_cast<int>(trial_branch[i]));
      s.water_volume = trial_water_volume[i];
      s.solid_volume = trial_solid_volume[i];
      s.release_modulus = trial_release_modulus[i];
      s.converged = true;
    } else if (density_ok) {
      s = soil_state(constants_, rho0 / rho, from, damage, pressure_guess, pore_guess);
    }
    // A trial serves one corrector at most (the compaction may change there).
    trial_density[i] = std::nan("");
    if (!density_ok || !s.converged || !std::isfinite(s.pressure) || !(s.bulk_modulus > 0.0)) {
#pragma omp critical(three_phase_soil_failure)
      if (failed < 0 || static_cast<std::int64_t>(i) < failed) {
        failed = static_cast<std::int64_t>(i);
        failed_quantity = density_ok ? "pressure" : "density";
        failed_detail = density_ok
                            ? fmt::format(
                                  "three-phase soil EOS: no converged pressure at density {} kg/m^3 "
                                  "after {} iterations (damage {})",
                                  rho, s.iterations, damage)
                            : fmt::format("three-phase soil EOS: density {} kg/m^3 is not positive", rho);
      }
      continue;
    }
    const double v = rho0 / rho;
    pts.pressure[i] = s.pressure - p0;
    pts.sound_speed[i] = std::sqrt(s.bulk_modulus / rho);
    pts.stable_sound_speed[i] = std::sqrt(std::max(s.release_modulus, s.bulk_modulus) / rho);
    if (!commit) {
      trial_density[i] = rho;
      trial_damage[i] = damage;
      trial_pressure[i] = s.pressure;
      trial_pore_pressure[i] = s.pore_pressure;
      trial_pore_volume[i] = s.pore_volume;
      trial_bulk_modulus[i] = s.bulk_modulus;
      trial_branch[i] = static_cast<double>(s.branch);
      trial_water_volume[i] = s.water_volume;
      trial_solid_volume[i] = s.solid_volume;
      trial_release_modulus[i] = s.release_modulus;
      continue;
    }
    branch[i] = static_cast<double>(s.branch);
    pore_pressure[i] = s.pore_pressure - p0;
    pore_volume[i] = s.pore_volume;
    if (s.branch == SoilBranch::loading) {
      // New maximum compaction: the point now sits where loading and
      // unloading meet. The sound speed reported is the stiffer unloading
      // one, since the next step may release (theory section, "sound speed").
      min_volume[i] = v;
      max_pressure[i] = s.pressure - p0;
      max_pore_pressure[i] = s.pore_pressure - p0;
      // The loading solve's last evaluation was at this state (p above the
      // cut-off), so its phase volumes are v_w(p_b,max) and v_s(p_max).
      max_water_volume[i] = s.water_volume;
      max_solid_volume[i] = s.solid_volume;
      const double release =
          soil_unloading_modulus(constants_, v, s.pressure, s.pore_pressure, s.water_volume, s.solid_volume);
      if (release > s.bulk_modulus) pts.sound_speed[i] = std::sqrt(release / rho);
    }
  }
  if (failed >= 0) throw NumericalError(EntityKind::material_point, failed, failed_quantity, failed_detail);
}

std::shared_ptr<const ThreePhaseSoilEos> make_three_phase_soil_eos(Parameters& p) {
  ThreePhaseSoilConstants c;
  double solid_density = 0.0, water_density = 0.0;
  double solid = 0.0, water = 0.0, air = 0.0;
  // Grain density may be called by its soil-mechanics name.
  const bool grain_alias = p.has("grain_density");
  if (grain_alias && p.has("solid_density"))
    p.fail("grain_density", "give grain_density or solid_density, not both");
  const PhaseKeys solid_keys{grain_alias ? "grain_density" : "solid_density",
                             "solid_sound_speed",
                             "solid_exponent",
                             2650.0,
                             4500.0,
                             3.0};
  const PhaseKeys water_keys{"water_density", "water_sound_speed", "water_exponent", 1000.0, 1500.0, 7.0};
  c.solid = read_tait(p, solid_keys, 0.0, solid_density);
  c.water = read_tait(p, water_keys, 0.0, water_density);
  read_fractions(p, solid_density, solid, water, air);
  c.solid.fraction = solid;
  c.water.fraction = water;

  const double air_density = p.positive("air_density", 1.2);
  const double air_sound_speed = p.positive("air_sound_speed", 340.0);
  c.air.fraction = air;
  c.air.exponent = p.positive("air_exponent", 1.4);
  c.air.inverse_exponent = 1.0 / c.air.exponent;
  c.ambient_pressure = air_density * air_sound_speed * air_sound_speed / c.air.exponent;  // eq. 15

  const double friction_coefficient = p.number("friction_coefficient");
  if (!(friction_coefficient >= 0.0)) p.fail("friction_coefficient", "must not be negative");
  const double friction_modulus = p.number("friction_modulus");
  if (!(friction_modulus >= 0.0)) p.fail("friction_modulus", "must not be negative (Pa)");
  c.friction = friction_coefficient * friction_modulus;
  c.bond_modulus = p.number("bond_modulus");
  if (!(c.bond_modulus >= 0.0)) p.fail("bond_modulus", "must not be negative (Pa)");
  c.tensile_strength = p.non_negative("tensile_strength", 0.0);

  if (!(c.pore_fraction() > 0.0))
    p.fail("water_fraction", "the soil needs pore space: water_fraction + air_fraction must be positive");
  if (!(solid + water > 0.0))
    p.fail("solid_fraction", "grains or water are needed (the unloading branch is their elastic response)");
  // The cut-off must lie where the grain and water laws still give a density.
  const double spinodal = std::min(c.solid.fraction > 0.0 ? c.solid.bulk_modulus / c.solid.exponent : 1e300,
                                   c.water.fraction > 0.0 ? c.water.bulk_modulus / c.water.exponent : 1e300);
  if (!(c.tensile_strength < 0.5 * spinodal))
    p.fail("tensile_strength",
           fmt::format("must stay below {} Pa, half the spinodal tension of the grain/water "
                       "laws (eqs. 13-14)",
                       0.5 * spinodal));
  const double rho0 = solid * solid_density + water * water_density + air * air_density;
  return std::make_shared<const ThreePhaseSoilEos>(c, rho0);
}

CAMOUFLET_REGISTER_EOS("three_phase_soil", [](Parameters& p) -> std::shared_ptr<const EquationOfState> {
  return make_three_phase_soil_eos(p);
});

}  // namespace camouflet
