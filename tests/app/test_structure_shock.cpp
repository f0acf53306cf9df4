// The in-structure shock tools of scripts/structure_shock.py against analytic
// answers (cases in tests/app/structure_shock_cases.py):
// * the zero-phase low-pass: a sine at the cut-off comes out 3.01 dB down
//   (within 0.1 dB), one at a tenth of it within 0.01 dB of the Butterworth
//   gain 1 / (1 + (f / 1.2465 f_c)^4), and a pulse keeps its peak time;
// * the shock response spectrum of a 1 ms half-sine base pulse, undamped,
//   against the closed-form response (forced part and residual), within 2 %;
// * the damped (5 %) spectrum of an irregular record against a direct
//   integration of the oscillator (scipy's solve_ivp at tolerance 1e-10),
//   within 0.1 %.
#include <gtest/gtest.h>

#include <map>
#include <sstream>
#include <string>

#include "common/verification.hpp"
#include "case/run_executable.hpp"

namespace {

struct Case {
  double expected = 0.0, computed = 0.0;
};

std::map<std::string, Case> run_cases() {
  const std::string script = std::string(CAMOUFLET_SOURCE_DIR) + "/tests/app/structure_shock_cases.py";
  const auto r = camouflet::test::run_camouflet_raw("/usr/bin/python3 '" + script + "'");
  EXPECT_EQ(r.status, 0) << r.output;
  std::map<std::string, Case> out;
  std::istringstream in(r.output);
  for (std::string name; in >> name;) {
    Case c;
    in >> c.expected >> c.computed;
    out[name] = c;
  }
  return out;
}

TEST(StructureShock, FilterAndShockSpectraAgainstAnalyticAnswers) {
  if (camouflet::test::run_camouflet_raw("/usr/bin/python3 -c 'import scipy'").status != 0)
    GTEST_SKIP() << "python3-scipy is not installed (scripts/setup.sh installs it)";
  const auto cases = run_cases();
  ASSERT_EQ(cases.size(), 12u);
  using camouflet::test::verify;
  const auto& gain = cases.at("filter_gain_at_cutoff_db");
  verify({"Zero-phase low-pass (order 2, forward and backward), 1 kHz cut-off: gain of a 1 kHz sine",
          "-10 log10 2 = -3.01 dB by construction", gain.expected, gain.computed, 0.1, false, "dB"});
  const auto& pass = cases.at("filter_gain_at_tenth_cutoff_db");
  verify({"Zero-phase low-pass, 1 kHz cut-off: gain of a 100 Hz sine", "1 / (1 + (f / 1.2465 f_c)^4) (Butterworth)",
          pass.expected, pass.computed, 0.01, false, "dB"});
  const auto& shift = cases.at("filter_peak_shift_s");
  verify({"Zero-phase low-pass, 1 kHz cut-off: peak time of a 2 ms Gaussian pulse", "unchanged (zero phase), 1 sample",
          0.0, shift.computed, 5e-5, false, "s"});
  for (const char* f : {"37", "113", "317", "731", "1290", "3170"}) {
    const auto& c = cases.at(std::string("half_sine_srs_") + f + "Hz");
    verify({std::string("SRS of a 1 ms, 1000 m/s^2 half-sine base pulse, undamped, absolute acceleration at ") + f +
                " Hz",
            "closed-form response, forced part and residual", c.expected, c.computed, 0.02, true, "m/s^2"});
  }
  for (const char* f : {"60", "250", "900"}) {
    const auto& c = cases.at(std::string("direct_pv_") + f + "Hz");
    verify({std::string("SRS of an irregular record, 5 % damping, pseudo-velocity at ") + f + " Hz",
            "direct integration of the oscillator (solve_ivp, rtol 1e-10)", c.expected, c.computed, 1e-3, true,
            "m/s"});
  }
}

}  // namespace
