#pragma once
// Concrete presets, also reachable by name through preset_registry().
#include "materials/registry.hpp"

namespace camouflet {

// Wang et al. 2005 Table 3 + Autodyn CONC-35MPA fill-ins (RHT + P-alpha).
MaterialPreset concrete_35mpa_wang2005();

}  // namespace camouflet
