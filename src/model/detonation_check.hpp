#pragma once
// Bad input: a detonation point must lie in an explosive part,
// otherwise the charge would silently never burn. The case reader (and
// `camouflet check`) calls this once the mesh, particles and materials are
// known; it throws InputError at the detonation point's location in the case.
#include "model/model.hpp"

namespace camouflet {

// True for a material that burns from detonation points (a JWL EOS).
bool is_explosive(const Material& material);

// Throws InputError (at model.detonation_where[k], or the run block when that
// is missing) for the first detonation point that lies in no element and near
// no particle (within one particle spacing) of an explosive part. Points on an
// element's boundary count as inside (a charge lit on the axis or on its surface).
void check_detonation_points(const Model& model);

}  // namespace camouflet
