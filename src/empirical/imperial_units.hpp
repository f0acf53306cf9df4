#pragma once
// Exact conversion factors for the US customary units in which TM 5-855-1
// states its ground-shock equations (docs/theory/tm5-855-1.md). The
// definitions are exact by international agreement (1959 yard and pound,
// standard gravity of the 3rd CGPM, 1901).
namespace camouflet::empirical::imperial {

inline constexpr double foot_m = 0.3048;             // m per ft
inline constexpr double pound_kg = 0.45359237;       // kg per lb (avoirdupois)
inline constexpr double standard_gravity = 9.80665;  // m/s^2 per g
inline constexpr double psi_Pa = 6894.757293168361;  // Pa per lbf/in^2 = 0.45359237 * 9.80665 / 0.0254^2

}  // namespace camouflet::empirical::imperial
