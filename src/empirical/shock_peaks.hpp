#pragma once
// The four free-field peaks at one range, and the in-structure shock of
// Wang et al. 2005 §5.5: each free-field peak averaged over the range the
// structure spans, from its near face R1 to its far face R2.
#include "empirical/ground_shock.hpp"

namespace camouflet::empirical {

struct Charge {
  double mass = 0.0;      // kg of TNT
  double coupling = 1.0;  // f in (0, 1]: 1 for a fully contained burst (TM 5-855-1 ch. 5)
};

struct ShockPeaks {
  double stress = 0.0;        // Pa
  double velocity = 0.0;      // m/s
  double acceleration = 0.0;  // m/s^2
  double displacement = 0.0;  // m
};

// Peaks at range R (m) from the charge centre.
ShockPeaks free_field_peaks(const GroundShockLaw& law, const Charge& charge, double range);

// (1 / (R2 - R1)) ∫_{R1}^{R2} peak(R) dR for every peak; R2 > R1 > 0 (m).
ShockPeaks in_structure_shock(const GroundShockLaw& law, const Charge& charge, double range_near,
                              double range_far);

}  // namespace camouflet::empirical
