#pragma once
// The 35 MPa concrete of Wang et al. 2005 built through the public path
// (preset + registry), as a case file would build it.
#include <cstdlib>
#include <memory>

#include "materials/concrete_presets.hpp"
#include "materials/p_alpha_eos.hpp"
#include "materials/registry.hpp"
#include "materials/rht_strength.hpp"

namespace camouflet::test {

// A call the compiler cannot drop links the models' objects (and so their
// registrations) into the test executable, which links the materials
// library as an ordinary archive.
inline void link_concrete_models() {
  if (std::getenv("CAMOUFLET_TEST_NEVER_SET_LINK_ONLY") != nullptr) {
    Parameters none;
    (void)make_p_alpha_eos(none);
    (void)make_rht_strength(none);
    (void)concrete_35mpa_wang2005();
  }
}

inline std::shared_ptr<const Material> concrete_35mpa(Parameters eos = {}, Parameters strength = {}) {
  link_concrete_models();
  return make_material("concrete", "concrete_35mpa_wang2005", SourceLocation{}, std::move(eos),
                       std::move(strength), Parameters{});
}

}  // namespace camouflet::test
