#pragma once
// What a run reports: its energy balance, the limit that set the time step,
// and how it ended. Plain records that the solver fills and the output layer
// and the particle system read, so they sit below both.
#include <cstdint>
#include <string>

namespace camouflet {

// Energies in J, accumulated from the start of the run. In axisymmetric mode
// they are for the full 2 pi revolution; in plane strain per metre of depth.
struct EnergyBalance {
  double kinetic = 0.0;
  double internal = 0.0;
  double hourglass = 0.0;
  double viscous = 0.0;         // dissipated by artificial viscosity (contained in internal)
  double boundary_work = 0.0;   // work done on the model by boundary forces and loads
  double eroded = 0.0;          // internal energy held by elements when they were eroded
  double initial_total = 0.0;   // kinetic + internal at t = 0
  // |E_kin + E_int + E_hg + E_eroded - E_0 - W_boundary| / max(E_0 + |W_boundary|, E_kin + E_int + E_hg + E_eroded)
  double relative_error = 0.0;
};

struct TimeStepLimit {
  double dt = 0.0;
  std::string reason;  // e.g. "element 1234 (soil): l/(c+|v|)"
};

struct RunSummary {
  double time = 0.0;          // s, final simulated time
  std::int64_t cycles = 0;
  double wall_seconds = 0.0;
  EnergyBalance energy;
  TimeStepLimit last_limit;
  std::string stop_reason;    // "end time reached", "max cycles reached", or the failure
  bool failed = false;
};

}  // namespace camouflet
