#pragma once
// Preset `sandy_clay_wang2005`: the sandy clay of Wang, Lu, Hao, Chong 2005,
// Tables 1-2, with the three-phase soil EOS, damage and strength; and
// `sandy_clay_wang2005_seismic`, the same soil with the skeleton's friction
// modulus K_p calibrated to Table 1's seismic velocity (theory section 12).
#include "materials/registry.hpp"

namespace camouflet {

MaterialPreset sandy_clay_wang2005();
MaterialPreset sandy_clay_wang2005_seismic();

// K_p (Pa) that gives the three-phase soil of `eos` (friction coefficient f,
// bond modulus E0, phases) the small-strain P-wave speed `seismic_velocity`
// (m/s) with shear modulus `shear_modulus` (Pa): the hand derivation of the
// initial tangent modulus (theory section 5) solved for K_p.
double friction_modulus_for_seismic_velocity(const Parameters& eos, double shear_modulus,
                                             double seismic_velocity);

}  // namespace camouflet
