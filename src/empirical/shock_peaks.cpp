#include "empirical/shock_peaks.hpp"

namespace camouflet::empirical {

ShockPeaks free_field_peaks(const GroundShockLaw& law, const Charge& charge, double range) {
  const auto at = [&](const PowerLaw& q) { return q.value(charge.mass, charge.coupling, range); };
  return ShockPeaks{at(law.stress), at(law.velocity), at(law.acceleration), at(law.displacement)};
}

ShockPeaks in_structure_shock(const GroundShockLaw& law, const Charge& charge, double range_near,
                              double range_far) {
  const auto mean = [&](const PowerLaw& q) {
    return q.span_average(charge.mass, charge.coupling, range_near, range_far);
  };
  return ShockPeaks{mean(law.stress), mean(law.velocity), mean(law.acceleration), mean(law.displacement)};
}

}  // namespace camouflet::empirical
