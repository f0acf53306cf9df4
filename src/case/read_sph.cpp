// [sph]: the numerical SPH settings (kernel, smoothing factor and bounds,
// viscosity, artificial stress, XSPH, kernel correction). Kept as Parameters
// in the model; read here once so that `camouflet check` refuses bad values.
#include "case/sections.hpp"
#include "sph/sph_options.hpp"

namespace camouflet::case_detail {

void read_sph(TomlReader& sph, Model& model) {
  model.sph = sph.parameters();
  Parameters check = model.sph;
  sph::read_sph_options(check);
  check.finish();
}

}  // namespace camouflet::case_detail
