// [sph]: the numerical SPH settings (kernel, smoothing factor and bounds,
// viscosity, artificial stress, XSPH, kernel correction), read once into the
// model's typed record, so that `camouflet check` refuses bad values.
#include "case/sections.hpp"
#include "sph/sph_options.hpp"

namespace camouflet::case_detail {

void read_sph(TomlReader& sph, Model& model) {
  Parameters block = sph.parameters();
  model.sph = sph::read_sph_options(block);
  block.finish();
}

}  // namespace camouflet::case_detail
