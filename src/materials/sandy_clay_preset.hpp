#pragma once
// Preset `sandy_clay_wang2005`: the sandy clay of Wang, Lu, Hao, Chong 2005,
// Tables 1-2, with the three-phase soil EOS, damage and strength.
#include "materials/registry.hpp"

namespace camouflet {

MaterialPreset sandy_clay_wang2005();

}  // namespace camouflet
